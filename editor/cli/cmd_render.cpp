// photowalk render: one frame of a scene to a PNG, offscreen (lavapipe when there is no GPU).
#include <algorithm>
#include <filesystem>
#include <cstdio>
#include <string>

#include "editor/cli/command.h"
#include "engine/io/model_io.h"
#include "modeling/pipeline.h"
#include "engine/gpu/renderer.h"
#include "engine/scene/camera.h"

namespace pw::editor {
namespace {

constexpr const char* kUsage =
    "usage: photowalk render SCENE -o OUT.png [--size WxH] [--viewpoint N|NAME] [--camera-from SHOT.json]\n"
    "                        [--cpu] [--msaa N]\n\n"
    "Renders SCENE (a model file, or 'sample' for the built-in room) from one of its\n"
    "viewpoints into a PNG (or .jpg), with the VRML97 lighting model.\n\n"
    "  -o, --output OUT.png  where the frame goes (written atomically)\n"
    "  --size WxH            frame size in pixels (default 1280x720)\n"
    "  --viewpoint N|NAME    the scene's Nth viewpoint, from 1, or the one with that\n"
    "                        description (default 1; a scene without viewpoints is\n"
    "                        seen whole from +Z)\n"
    "  --camera-from SHOT    the camera that took the shot's photo, as measured, with its\n"
    "                        focal length and principal point, at the photo's size: the\n"
    "                        frame lines up with the photo pixel for pixel when SCENE was\n"
    "                        built from that shot (its first corridor), as its Photo\n"
    "                        viewpoint does; with --size, the photo scaled to the frame's\n"
    "                        smaller side about its centre; a shot whose lens has\n"
    "                        distortion is drawn through it (the photo's size only)\n"
    "  --cpu                 use the CPU renderer (lavapipe) even if a GPU exists\n"
    "                        (as PW_DEVICE=cpu)\n"
    "  --msaa N              samples per pixel: 1, 2, 4 (default) or 8, as the device allows\n"
    "  --allow-folder DIR    let the scene's Inlines and textures come from DIR too (by\n"
    "                        default only from the scene's own folder; repeatable)\n\n"
    "With Vulkan validation on (PW_VALIDATION=1, or a Debug build) any validation message\n"
    "fails the command (exit 1) and no image is written.\n";

int runRender(Args& args) {
  const auto output = args.value("--output", "-o");
  const auto sizeText = args.value("--size");
  const auto viewpointText = args.value("--viewpoint");
  const auto cameraFrom = args.value("--camera-from");
  const auto msaaText = args.value("--msaa");
  const std::vector<std::string> allowed = args.values("--allow-folder");
  engine::RendererOptions options;
  options.forceCpu = args.flag("--cpu");
  const std::vector<std::string> positionals = args.positionals();
  if (auto finished = args.finish(); !finished) return fail(finished.message());
  if (positionals.size() != 1) return fail("render takes one scene; see photowalk render --help");
  if (!output) return fail("render needs -o OUT.png");
  if (auto image = checkImageExtension(*output, "-o"); !image) return fail(image.message());
  std::vector<NamedInput> inputs{{"the model", positionals[0]}};
  if (cameraFrom) inputs.push_back({"the --camera-from shot", *cameraFrom});
  if (auto distinct = checkNotAnInput(*output, "-o", inputs); !distinct) return fail(distinct.message());

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
  std::vector<std::string> warnings;
  auto scene = engine::loadModel(positionals[0], &warnings,
                                 std::vector<std::filesystem::path>(allowed.begin(), allowed.end()));
  for (const std::string& w : warnings) printWarning(w);
  if (!scene) return fail(scene.message());
  if (viewpointText && cameraFrom) return fail("give --viewpoint or --camera-from, not both");
  engine::Camera camera;
  metrology::Intrinsics lens;
  if (cameraFrom) {
    // The shot's measured camera, as `build` makes the Photo viewpoint of a model built
    // from it; at another --size the renderer fits the photo's lens to the frame.
    auto shotCamera = modeling::shotCamera(*cameraFrom, &lens);
    if (!shotCamera) return fail(shotCamera.message());
    camera = *shotCamera;
    if (!sizeText) size = {camera.intrinsics->imageWidth, camera.intrinsics->imageHeight};
    if (!lens.distortion.isNone() && sizeText) {
      return fail("--size: the shot's lens has distortion; its camera is drawn at the photo's own size only");
    }
  } else {
    const size_t count = scene->viewpoints.size();
    size_t index = 0;
    if (viewpointText) {
      const auto byName = std::find_if(scene->viewpoints.begin(), scene->viewpoints.end(),
                                       [&](const engine::Viewpoint& v) { return v.description == *viewpointText; });
      if (byName != scene->viewpoints.end()) {
        index = static_cast<size_t>(byName - scene->viewpoints.begin());
      } else {
        auto number = parsePositiveInt(*viewpointText, "--viewpoint");
        if (!number) {
          std::string names;
          for (const auto& v : scene->viewpoints) names += (names.empty() ? "" : ", ") + ("\"" + v.description + "\"");
          return fail("--viewpoint " + *viewpointText + ": no viewpoint of that name or number in " + positionals[0] +
                      (names.empty() ? " (it has none)" : " (it has " + names + ")"));
        }
        if (count == 0 ? *number != 1 : size_t(*number) > count) {
          return fail("--viewpoint " + std::to_string(*number) + " is out of range: " + positionals[0] + " has " +
                      std::to_string(count) + " viewpoint" + (count == 1 ? "" : "s"));
        }
        index = size_t(*number - 1);
      }
    }
    camera = engine::cameraFromViewpoint(count == 0 ? engine::defaultViewpoint(*scene) : scene->viewpoints[index]);
  }

  auto renderer = engine::Renderer::create(options);
  if (!renderer) return fail(renderer.message());
  for (const std::string& note : (*renderer)->notes()) printNote(note);
  if (auto uploaded = (*renderer)->setScene(*scene); !uploaded) return fail(uploaded.message());
  Result<engine::Image> image = engine::Image{};
  if (!lens.distortion.isNone()) {
    // A pinhole frame large enough for the whole photo, then through the lens.
    const modeling::LensFrame frame = modeling::lensFrame(camera, lens, size.first, size.second);
    image = (*renderer)->renderToImage(frame.camera, frame.width, frame.height);
    if (image) image = modeling::distortFrame(*image, frame, lens, size.first, size.second);
  } else {
    image = (*renderer)->renderToImage(camera, size.first, size.second);
  }
  if (!image) return fail(image.message());
  // A frame drawn while the layers objected is not trusted: nothing is written.
  if (auto clean = (*renderer)->validationStatus(); !clean) return fail(clean.message());
  if (auto saved = engine::saveImage(*output, *image); !saved) return fail(saved.message());
  std::printf("%s: %dx%d, %s, %dx MSAA\n", output->c_str(), size.first, size.second, (*renderer)->deviceName().c_str(),
              (*renderer)->msaaSamples());
  return kExitOk;
}

}  // namespace

PW_COMMAND(render, "render", "draw a scene's viewpoint to a PNG (offscreen, lavapipe without a GPU)", kUsage, runRender);

}  // namespace pw::editor
