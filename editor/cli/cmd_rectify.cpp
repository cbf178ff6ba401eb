// photowalk rectify: the five planes of a corridor as true-scale, fronto-parallel
// textures (issue 3).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "base/atomic_file.h"
#include "editor/cli/command.h"
#include "modeling/shot_file.h"
#include "metrology/measure.h"
#include "metrology/rectify.h"

namespace pw::editor {
namespace {
namespace fs = std::filesystem;

constexpr const char* kUsage =
    "usage: photowalk rectify SHOT.json -o DIR [--method general|seed] [--px-per-m N] [--max-side N]\n\n"
    "Measures the corridor, then removes the perspective from each of its planes and\n"
    "writes DIR/far_wall.png, left_wall.png, right_wall.png, floor.png, ceiling.png at\n"
    "true aspect ratio, and DIR/planes.json with each plane's true size in metres, its\n"
    "size in pixels and its corners in the model frame (top-left, top-right,\n"
    "bottom-right, bottom-left of the texture). Walls are upright as seen from inside,\n"
    "the floor has its far edge at the top, the ceiling is as seen looking up.\n\n"
    "  -o, --output DIR  folder for the textures (created if missing)\n"
    "  --method M        general (default) or seed, as for measure\n"
    "  --px-per-m N      texture resolution (default: the photo's best on each plane)\n"
    "  --max-side N      cap on a texture's longer side in pixels (default 4096)\n";

Status writePng(const fs::path& path, const cv::Mat& image) {
  return writeViaTempFile(path, [&](const fs::path& temp) -> Status {
    bool ok = false;
    try {
      ok = cv::imwrite(temp.string(), image);
    } catch (const cv::Exception&) {
      ok = false;
    }
    if (!ok) return makeError(path.string() + ": cannot write the PNG");
    return {};
  });
}

int runRectify(Args& args) {
  metrology::MeasureOptions measureOptions;
  metrology::RectifyOptions options;
  const std::optional<std::string> output = args.value("--output", "-o");
  const std::optional<std::string> method = args.value("--method");
  const std::optional<std::string> pxPerM = args.value("--px-per-m");
  const std::optional<std::string> maxSide = args.value("--max-side");
  const std::vector<std::string> positionals = args.positionals();
  if (auto finished = args.finish(); !finished) return fail(finished.message());
  if (positionals.size() != 1) return fail("rectify takes one shot file; see photowalk rectify --help");
  if (!output) return fail("rectify needs -o DIR, the folder for the textures");
  if (method) {
    if (*method == "general") measureOptions.method = metrology::Method::kGeneral;
    else if (*method == "seed") measureOptions.method = metrology::Method::kSeed;
    else return fail("--method must be general or seed, not '" + *method + "'");
  }
  if (pxPerM) {
    auto v = parseNumber(*pxPerM, "--px-per-m");
    if (!v) return fail(v.message());
    if (!(*v > 0)) return fail("--px-per-m must be positive");
    options.pxPerM = *v;
  }
  if (maxSide) {
    auto v = parseNumber(*maxSide, "--max-side");
    if (!v) return fail(v.message());
    if (!(*v >= 1 && *v <= 32768) || *v != std::floor(*v)) return fail("--max-side must be a whole number 1..32768");
    options.maxSidePx = static_cast<int>(*v);
  }
  const std::string& shotPath = positionals[0];

  auto loaded = modeling::loadShot(shotPath);
  if (!loaded) return fail(loaded.message());
  for (const std::string& warning : loaded->warnings) printWarning(warning);
  auto measurement = metrology::measureCorridor(loaded->shot, measureOptions);
  if (!measurement) return fail(shotPath + ": " + measurement.message());
  auto planes = metrology::rectifyCorridor(loaded->image, *measurement, options);
  if (!planes) return fail(shotPath + ": " + planes.message());

  const fs::path dir = *output;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (!fs::is_directory(dir, ec)) return fail(dir.string() + ": cannot create the output folder");

  // Never over an input: a shot or photo kept in the output folder under a plane's name.
  const std::vector<NamedInput> inputs{{"the shot", shotPath}, {"the shot's photo", loaded->shot.imagePath}};
  for (int p = 0; p < metrology::kPlaneCount; ++p) {
    const fs::path file = dir / (std::string(metrology::planeName(static_cast<metrology::Plane>(p))) + ".png");
    if (auto distinct = checkNotAnInput(file.string(), "-o", inputs); !distinct) return fail(distinct.message());
  }
  if (auto distinct = checkNotAnInput((dir / "planes.json").string(), "-o", inputs); !distinct) {
    return fail(distinct.message());
  }

  nlohmann::ordered_json doc;
  doc["shot"] = shotPath;
  doc["method"] = metrology::methodName(measurement->method);
  doc["width_m"] = measurement->size.widthM;
  doc["height_m"] = measurement->size.heightM;
  doc["length_m"] = measurement->size.lengthM;
  doc["corners_order"] = "top-left, top-right, bottom-right, bottom-left of the texture";
  nlohmann::ordered_json list = nlohmann::ordered_json::object();
  for (int p = 0; p < metrology::kPlaneCount; ++p) {
    const auto plane = static_cast<metrology::Plane>(p);
    const metrology::RectifiedPlane& r = (*planes)[p];
    const std::string file = std::string(metrology::planeName(plane)) + ".png";
    if (Status written = writePng(dir / file, r.image); !written) return fail(written.message());
    nlohmann::ordered_json corners = nlohmann::ordered_json::array(), names = nlohmann::ordered_json::array();
    const auto cornersM = metrology::planeCornersM(plane, measurement->size);
    for (int i = 0; i < 4; ++i) {
      corners.push_back({cornersM[i].x + 0.0, cornersM[i].y + 0.0, cornersM[i].z + 0.0});
      names.push_back(metrology::cornerName(metrology::kPlaneCorners[p][i]));
    }
    list[metrology::planeName(plane)] = {
        {"file", file},           {"width_m", r.widthM},           {"height_m", r.heightM},
        {"width_px", r.image.cols}, {"height_px", r.image.rows}, {"px_per_m", r.pxPerM},
        {"coverage", r.coverage}, {"corners", names},             {"corners_m", corners},
    };
  }
  doc["planes"] = list;
  if (Status written = writeFileAtomic(dir / "planes.json", doc.dump(1) + "\n"); !written) return fail(written.message());
  for (int p = 0; p < metrology::kPlaneCount; ++p) {
    const metrology::RectifiedPlane& r = (*planes)[p];
    std::printf("%-10s %7.3f x %6.3f m  %5d x %4d px  %6.1f px/m  coverage %3.0f%%\n",
                metrology::planeName(static_cast<metrology::Plane>(p)), r.widthM, r.heightM, r.image.cols, r.image.rows,
                r.pxPerM, 100.0 * r.coverage);
  }
  return kExitOk;
}

}  // namespace

PW_COMMAND(rectify, "rectify", "the corridor's planes as true-scale textures (PNG) from one photo", kUsage, runRectify);

}  // namespace pw::editor
