// photowalk convert IN OUT: converts a model between file formats, chosen by extension.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>

#include "editor/cli/command.h"
#include "engine/io/model_io.h"
#include "engine/gltf/gltf_writer.h"
#include "engine/vrml/vrml_writer.h"

namespace pw::editor {
namespace {

namespace fs = std::filesystem;

enum class Format { kUnknown, kVrml, kGltf };

Format outputFormat(const fs::path& path) {
  std::string name = path.filename().string();
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::tolower(c); });
  const auto ends = [&](const std::string& suffix) {
    return name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
  };
  if (ends(".wrl") || ends(".wrl.gz") || ends(".wrz")) return Format::kVrml;
  if (ends(".glb") || ends(".gltf")) return Format::kGltf;
  return Format::kUnknown;
}

int runConvert(Args& args) {
  const std::optional<std::string> title = args.value("--title");
  const bool jpeg = args.flag("--jpeg-textures");
  const bool quiet = args.flag("--quiet", "-q");
  const std::vector<std::string> allowed = args.values("--allow-folder");
  const std::vector<std::string> files = args.positionals();
  if (Status s = args.finish(); !s) return fail(s.message() + "; see photowalk convert --help");
  if (files.size() != 2) return fail("convert wants an input and an output file: photowalk convert IN OUT");
  const fs::path in = files[0], out = files[1];
  const Format format = outputFormat(out);
  if (format == Format::kUnknown) {
    return fail(out.string() + ": unknown output extension; use .wrl, .wrl.gz, .wrz, .glb or .gltf");
  }
  if (jpeg && format == Format::kGltf) return fail("--jpeg-textures is for VRML output; glTF embeds PNG textures");
  if (auto distinct = checkNotAnInput(out.string(), "the output", {{"the input model", in.string()}}); !distinct) {
    return fail(distinct.message());
  }

  std::vector<std::string> warnings;
  auto scene = engine::loadModel(in, &warnings, std::vector<fs::path>(allowed.begin(), allowed.end()));
  if (!quiet) {
    for (const std::string& w : warnings) printWarning(w);
  }
  if (!scene) return fail(scene.message());
  if (title) scene->title = *title;
  if (format == Format::kGltf) {
    if (Status s = engine::writeGltf(*scene, out); !s) return fail(s.message());
  } else {
    engine::VrmlWriteOptions options;
    options.jpegTextures = jpeg;
    if (Status s = engine::writeVrml(*scene, out, options); !s) return fail(s.message());
  }
  if (!quiet) {
    std::printf("%s: %zu shapes, %zu lights, %zu viewpoints -> %s\n", in.string().c_str(), scene->shapes.size(),
                scene->lights.size(), scene->viewpoints.size(), out.string().c_str());
  }
  return kExitOk;
}

}  // namespace

PW_COMMAND(convert, "convert", "convert a model between formats (VRML97, glTF 2.0)",
           "usage: photowalk convert IN OUT [--title TEXT] [--jpeg-textures] [--quiet]\n\n"
           "Reads IN (VRML97 .wrl/.wrz/.wrl.gz, glTF 2.0 .glb/.gltf, or 'sample') and writes OUT,\n"
           "its format chosen by extension:\n"
           "  .wrl, .wrz, .wrl.gz   VRML97 (output ending in .gz or .wrz is compressed); textures\n"
           "                        beside OUT as OUTSTEM_NAME.png (or .jpg with --jpeg-textures),\n"
           "                        referenced by relative urls\n"
           "  .glb, .gltf           glTF 2.0, binary or JSON, textures embedded\n\n"
           "  --title TEXT      the title of the output (default: the input's)\n"
           "  --jpeg-textures   VRML output: textures as JPEG (quality 92) instead of PNG\n"
           "  --quiet, -q       print nothing but errors\n"
           "  --allow-folder DIR  let IN's Inlines, textures and buffers come from DIR too\n"
           "                    (by default only from IN's own folder; repeatable)\n\n"
           "Warnings about the input (unsupported nodes, missing textures) go to stderr; the\n"
           "exit status is 1 with a one-line error when the input cannot be read or OUT written.\n",
           runConvert);

}  // namespace pw::editor
