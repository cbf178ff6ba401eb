// photowalk render: one frame of a scene to a PNG, offscreen (lavapipe when there is no GPU).
#include <charconv>
#include <cstdio>
#include <string>

#include "editor/command.h"
#include "editor/model_io.h"
#include "engine/gpu/renderer.h"
#include "engine/scene/camera.h"

namespace pw::editor {
namespace {

constexpr const char* kUsage =
    "usage: photowalk render SCENE -o OUT.png [--size WxH] [--viewpoint N] [--cpu] [--msaa N]\n\n"
    "Renders SCENE (a model file, or 'sample' for the built-in room) from one of its\n"
    "viewpoints into a PNG (or .jpg), with the VRML97 lighting model.\n\n"
    "  -o, --output OUT.png  where the frame goes (written atomically)\n"
    "  --size WxH            frame size in pixels (default 1280x720)\n"
    "  --viewpoint N         the scene's Nth viewpoint, from 1 (default 1; a scene\n"
    "                        without viewpoints is seen whole from +Z)\n"
    "  --cpu                 use the CPU renderer (lavapipe) even if a GPU exists\n"
    "                        (as PW_DEVICE=cpu)\n"
    "  --msaa N              samples per pixel: 1, 2, 4 (default) or 8, as the device allows\n";

Result<int> parsePositiveInt(const std::string& text, const char* option) {
  int value = 0;
  auto r = std::from_chars(text.data(), text.data() + text.size(), value);
  if (r.ec != std::errc() || r.ptr != text.data() + text.size() || value < 1) {
    return makeError(std::string(option) + " wants a whole number from 1, not '" + text + "'");
  }
  return value;
}

int runRender(Args& args) {
  const auto output = args.value("--output", "-o");
  const auto sizeText = args.value("--size");
  const auto viewpointText = args.value("--viewpoint");
  const auto msaaText = args.value("--msaa");
  engine::RendererOptions options;
  options.forceCpu = args.flag("--cpu");
  const std::vector<std::string> positionals = args.positionals();
  if (auto finished = args.finish(); !finished) return fail(finished.message());
  if (positionals.size() != 1) return fail("render takes one scene; see photowalk render --help");
  if (!output) return fail("render needs -o OUT.png");

  std::pair<int, int> size{1280, 720};
  if (sizeText) {
    auto parsed = parseSize(*sizeText, "--size");
    if (!parsed) return fail(parsed.message());
    size = *parsed;
  }
  if (msaaText) {
    auto msaa = parsePositiveInt(*msaaText, "--msaa");
    if (!msaa) return fail(msaa.message());
    options.msaaSamples = *msaa;
  }
  int viewpoint = 1;
  if (viewpointText) {
    auto parsed = parsePositiveInt(*viewpointText, "--viewpoint");
    if (!parsed) return fail(parsed.message());
    viewpoint = *parsed;
  }

  std::vector<std::string> warnings;
  auto scene = loadModel(positionals[0], &warnings);
  for (const std::string& w : warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  if (!scene) return fail(scene.message());
  const size_t viewpointCount = scene->viewpoints.size();
  if (viewpointCount == 0 ? viewpoint != 1 : size_t(viewpoint) > viewpointCount) {
    return fail("--viewpoint " + std::to_string(viewpoint) + " is out of range: " + positionals[0] + " has " +
                std::to_string(viewpointCount) + " viewpoint" + (viewpointCount == 1 ? "" : "s"));
  }
  const engine::Camera camera = engine::cameraFromViewpoint(
      viewpointCount == 0 ? engine::defaultViewpoint(*scene) : scene->viewpoints[size_t(viewpoint - 1)]);

  auto renderer = engine::Renderer::create(options);
  if (!renderer) return fail(renderer.message());
  for (const std::string& note : (*renderer)->notes()) std::fprintf(stderr, "note: %s\n", note.c_str());
  if (auto uploaded = (*renderer)->setScene(*scene); !uploaded) return fail(uploaded.message());
  auto image = (*renderer)->renderToImage(camera, size.first, size.second);
  if (!image) return fail(image.message());
  if (auto saved = engine::saveImage(*output, *image); !saved) return fail(saved.message());
  std::printf("%s: %dx%d, %s, %dx MSAA\n", output->c_str(), size.first, size.second, (*renderer)->deviceName().c_str(),
              (*renderer)->msaaSamples());
  return kExitOk;
}

}  // namespace

PW_COMMAND(render, "render", "draw a scene's viewpoint to a PNG (offscreen, lavapipe without a GPU)", kUsage, runRender);

}  // namespace pw::editor
