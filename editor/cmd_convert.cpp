// photowalk convert IN OUT: converts a model between file formats, chosen by extension.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>

#include "editor/command.h"
#include "engine/vrml/vrml_reader.h"
#include "engine/vrml/vrml_writer.h"

namespace pw::editor {
namespace {

namespace fs = std::filesystem;

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

bool isVrmlName(const fs::path& path) {
  const std::string name = lower(path.filename().string());
  auto ends = [&](const char* suffix) {
    const std::string s(suffix);
    return name.size() > s.size() && name.compare(name.size() - s.size(), s.size(), s) == 0;
  };
  return ends(".wrl") || ends(".wrl.gz") || ends(".wrz") || ends(".vrml");
}

void printDiagnostics(const engine::Diagnostics& diagnostics) {
  if (!diagnostics.empty()) std::fputs(diagnostics.format().c_str(), stderr);
}

int runConvert(Args& args) {
  const std::optional<std::string> title = args.value("--title");
  const bool jpeg = args.flag("--jpeg-textures");
  const bool quiet = args.flag("--quiet", "-q");
  const std::vector<std::string> files = args.positionals();
  if (Status s = args.finish(); !s) return fail(s.message() + "; see photowalk convert --help");
  if (files.size() != 2) return fail("convert wants an input and an output file: photowalk convert IN OUT");
  const fs::path in = files[0], out = files[1];
  if (!isVrmlName(in)) {
    return fail(in.string() + ": photowalk converts from VRML97 (.wrl, .wrl.gz, .wrz); unknown input extension");
  }
  const std::string outName = lower(out.filename().string());
  const bool gltf = outName.size() > 4 && (outName.ends_with(".glb") || outName.ends_with(".gltf"));
  if (gltf) return fail(out.string() + ": glTF export is not available in this build yet; write .wrl or .wrl.gz");
  if (!isVrmlName(out)) {
    return fail(out.string() + ": unknown output extension; use .wrl or .wrl.gz");
  }
  engine::Diagnostics diagnostics;
  auto scene = engine::readVrml(in, &diagnostics);
  if (!quiet) printDiagnostics(diagnostics);
  if (!scene) return fail(scene.message());
  engine::VrmlWriteOptions options;
  options.jpegTextures = jpeg;
  if (title) options.title = *title;
  if (Status s = engine::writeVrml(*scene, out, options); !s) return fail(s.message());
  if (!quiet) {
    std::printf("%s: %zu shapes, %zu lights, %zu viewpoints -> %s\n", in.string().c_str(), scene->shapes.size(),
                scene->lights.size(), scene->viewpoints.size(), out.string().c_str());
  }
  return kExitOk;
}

}  // namespace

PW_COMMAND(convert, "convert", "convert a model between formats (VRML97 .wrl/.wrl.gz)",
           "usage: photowalk convert IN OUT [--title TEXT] [--jpeg-textures] [--quiet]\n\n"
           "Reads IN and writes OUT, choosing the formats by extension:\n"
           "  .wrl, .wrz, .wrl.gz   VRML97 (gzip-compressed input is recognised whatever its name;\n"
           "                        output ending in .gz or .wrz is compressed)\n"
           "Textures are written beside OUT as OUTSTEM_NAME.png (or .jpg with --jpeg-textures)\n"
           "and referenced by relative urls.\n\n"
           "  --title TEXT      the WorldInfo title of the output (default: the input's)\n"
           "  --jpeg-textures   write textures as JPEG (quality 92) instead of PNG\n"
           "  --quiet, -q       print nothing but errors\n\n"
           "Warnings about the input (unsupported nodes, missing textures) go to stderr; the\n"
           "exit status is 1 with a one-line error when the input cannot be read or OUT written.\n",
           runConvert);

}  // namespace pw::editor
