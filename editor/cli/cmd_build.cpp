// photowalk build: shots (photo + camera + corners) to a true-scale, textured,
// walkable model in VRML97 (and glTF 2.0): one corridor, or a building of several.
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "base/staging.h"
#include "editor/cli/command.h"
#include "modeling/layout.h"
#include "modeling/pipeline.h"
#include "modeling/shot_file.h"
#include "engine/gltf/gltf_writer.h"
#include "engine/vrml/vrml_writer.h"

namespace pw::editor {
namespace {
namespace fs = std::filesystem;

constexpr const char* kUsage =
    "usage: photowalk build SHOT.json [SHOT2.json ...] -o OUT.wrl [options]\n"
    "       photowalk build --layout LAYOUT.json -o OUT.wrl [options]\n\n"
    "Measures each shot, cuts the floor, ceiling, walls and far wall out of its photo as\n"
    "true-scale textures and writes the model: OUT.wrl (or .wrl.gz) with the textures\n"
    "beside it. Several shots without a layout are joined end to end; a layout file\n"
    "places them and opens the walls between them (README: Layout files).\n\n"
    "  -o, --output OUT.wrl  the model (written atomically; missing folders are created)\n"
    "  --layout LAYOUT.json  a building of several corridors\n"
    "  --gltf OUT.glb        also write binary glTF 2.0 (.gltf: JSON with embedded data)\n"
    "  --lit                 Materials, lights along the ceiling and the headlight (the\n"
    "                        seed paper's rendering); default: photo-lit, the textures\n"
    "                        carry the photo's own light and are drawn unlit\n"
    "  --px-per-m N          texture resolution (default: the photo's own best on each plane)\n"
    "  --photo-only          only what the photo shows: no detail added where it saw a\n"
    "                        surface coarsely, no texture where it did not see it, and\n"
    "                        the corridor left open behind the camera\n"
    "  --no-detail           synthesize what the photo did not see, but add no detail where\n"
    "                        it saw a surface coarsely\n"
    "  --jpeg                textures as JPEG instead of PNG\n"
    "  --force               replace files beside OUT.wrl that have a texture's name but\n"
    "                        that the model there does not name (by default such a texture\n"
    "                        gets a free name: OUT_s_floor_2.png)\n"
    "  --sigma-px S          corner standard deviation for the printed ± (default 1)\n";

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// The folders missing above `file`, created, deepest last, so that a failed build can
// take them away again. One that cannot be made is left to the write to report.
std::vector<fs::path> createFoldersFor(const fs::path& file) {
  std::vector<fs::path> missing;
  std::error_code ec;
  for (fs::path folder = file.parent_path(); !folder.empty() && !fs::exists(folder, ec); folder = folder.parent_path()) {
    missing.insert(missing.begin(), folder);
    if (folder == folder.parent_path()) break;
  }
  std::vector<fs::path> created;
  for (const fs::path& folder : missing) {
    if (!fs::create_directory(folder, ec)) break;
    created.push_back(folder);
  }
  return created;
}

void removeFolders(const std::vector<fs::path>& folders) {
  std::error_code ec;
  for (auto folder = folders.rbegin(); folder != folders.rend(); ++folder) fs::remove(*folder, ec);  // only if empty
}

int runBuild(Args& args) {
  const auto output = args.value("--output", "-o");
  const auto layoutPath = args.value("--layout");
  const auto gltfPath = args.value("--gltf");
  const auto pxPerMText = args.value("--px-per-m");
  const auto sigmaText = args.value("--sigma-px");
  modeling::ModelOptions options;
  options.lit = args.flag("--lit");
  options.photoOnly = args.flag("--photo-only");
  options.detail = !args.flag("--no-detail");
  engine::VrmlWriteOptions vrmlOptions;
  vrmlOptions.jpegTextures = args.flag("--jpeg");
  vrmlOptions.overwriteForeignFiles = args.flag("--force");
  const std::vector<std::string> shots = args.positionals();
  if (auto finished = args.finish(); !finished) return fail(finished.message());
  if (!output) return fail("build needs -o OUT.wrl");
  if (!endsWith(*output, ".wrl") && !endsWith(*output, ".wrl.gz") && !endsWith(*output, ".wrz")) {
    return fail(*output + ": the model is VRML97: name it .wrl or .wrl.gz (use --gltf for glTF)");
  }
  if (layoutPath && !shots.empty()) return fail("give shot files or --layout, not both");
  if (!layoutPath && shots.empty()) return fail("build needs a shot file (or --layout); see photowalk build --help");
  if (pxPerMText) {
    auto v = parseNumber(*pxPerMText, "--px-per-m");
    if (!v) return fail(v.message());
    if (*v < 1 || *v > 10000) return fail("--px-per-m must be between 1 and 10000");
    options.pxPerM = *v;
  }
  metrology::MeasureOptions measureOptions;
  if (sigmaText) {
    auto v = parseNumber(*sigmaText, "--sigma-px");
    if (!v) return fail(v.message());
    if (*v < 0) return fail("--sigma-px must be >= 0");
    measureOptions.cornerSigmaPx = *v;
  }

  // What runs killed before were writing here goes first, however far this one gets.
  removeLeftoversOf(*output);
  if (gltfPath) removeLeftoversOf(*gltfPath);

  modeling::Layout layout;
  if (layoutPath) {
    auto read = modeling::readLayoutFile(*layoutPath);
    if (!read) return fail(read.message());
    layout = std::move(*read);
  } else {
    layout = modeling::chainLayout(std::vector<fs::path>(shots.begin(), shots.end()));
  }

  // Never over an input: the layout, a shot or a shot's photo.
  std::vector<NamedInput> inputs;
  if (layoutPath) inputs.push_back({"the layout", *layoutPath});
  for (const modeling::LayoutEntry& entry : layout.corridors) {
    inputs.push_back({"a shot", entry.shot.string()});
    if (auto shot = modeling::readShotFile(entry.shot); shot) inputs.push_back({"a shot's photo", shot->imagePath});
  }
  if (auto distinct = checkNotAnInput(*output, "-o", inputs); !distinct) return fail(distinct.message());
  if (gltfPath) {
    if (auto distinct = checkNotAnInput(*gltfPath, "--gltf", inputs); !distinct) return fail(distinct.message());
  }

  auto model = modeling::buildModel(layout, options, measureOptions);
  if (!model) return fail(model.message());
  for (const std::string& warning : model->warnings) printWarning(warning);
  for (const modeling::CorridorOverlap& overlap : model->plan.overlaps) {
    std::fprintf(stderr, "warning: %s\n", modeling::overlapText(model->layout, overlap).c_str());
  }
  for (const modeling::CorridorModel& corridor : model->corridors) {
    for (const std::string& reason : corridor.leftPainted) {
      std::fprintf(stderr, "warning: %s: %s; left painted on the surfaces behind it\n", corridor.name.c_str(), reason.c_str());
    }
  }

  // Everything that can fail on the input has failed by now; write the files, into
  // folders made for them if need be (as tour does).
  // The glTF is written under a pending name and takes its own only once the VRML
  // model is in place: a failed build leaves the previous .glb and .wrl as they were.
  std::vector<fs::path> created = createFoldersFor(*output);
  fs::path pendingGltf;
  if (gltfPath) {
    const std::vector<fs::path> forGltf = createFoldersFor(*gltfPath);
    created.insert(created.end(), forGltf.begin(), forGltf.end());
    const fs::path target(*gltfPath);
    const std::string prefix = "." + target.stem().string() + ".pending-";
    removeStaleTemporaries(target.parent_path(), prefix);
    pendingGltf = target.parent_path() / (prefix + processIdText() + target.extension().string());
    if (auto written = engine::writeGltf(model->scene, pendingGltf); !written) {
      std::error_code ec;
      fs::remove(pendingGltf, ec);
      removeFolders(created);
      std::string message = written.message();
      if (const size_t at = message.find(pendingGltf.string()); at != std::string::npos) {
        message.replace(at, pendingGltf.string().size(), *gltfPath);
      }
      return fail(message);
    }
  }
  if (auto written = engine::writeVrml(model->scene, *output, vrmlOptions); !written) {
    std::error_code ec;
    if (gltfPath) fs::remove(pendingGltf, ec);
    removeFolders(created);
    return fail(written.message());
  }
  if (gltfPath) {
    std::error_code ec;
    fs::rename(pendingGltf, *gltfPath, ec);
    if (ec) {
      fs::remove(pendingGltf, ec);
      return fail(*gltfPath + ": cannot write: " + ec.message() + " (" + *output + " was written)");
    }
  }

  for (const modeling::CorridorModel& corridor : model->corridors) {
    const auto& m = corridor.measurement;
    std::printf("%s: width %.3f ± %.3f m, height %.3f ± %.3f m, length %.3f ± %.3f m\n", corridor.name.c_str(),
                m.size.widthM, m.sigma.widthM, m.size.heightM, m.sigma.heightM, m.size.lengthM, m.sigma.lengthM);
  }
  std::printf("model: %s (%zu shapes, %zu viewpoints)%s%s\n", output->c_str(), model->scene.shapes.size(),
              model->scene.viewpoints.size(), gltfPath ? ", glTF: " : "", gltfPath ? gltfPath->c_str() : "");
  return kExitOk;
}

}  // namespace

PW_COMMAND(build, "build", "photo(s) to a true-scale, textured, walkable model (VRML97, glTF)", kUsage, runBuild);

}  // namespace pw::editor
