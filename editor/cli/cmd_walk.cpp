// photowalk walk: a real-time first-person walk through a model, in a window.
#include <cstdio>
#include <string>

#include "editor/cli/command.h"
#include "editor/walk/replay.h"
#include "editor/walk/walk_window.h"
#include "engine/io/model_io.h"

namespace pw::editor {
namespace {

constexpr const char* kUsage =
    "usage: photowalk walk MODEL [--size WxH] [--no-vsync] [--cpu] [--msaa N] [--per-pixel-lighting]\n"
    "                      [--speed-scale K]\n"
    "                      [--replay SCRIPT] [--trace OUT.csv] [--screenshot-dir DIR] [--no-overlay]\n\n"
    "Opens a window and lets you walk through MODEL (.wrl, .wrl.gz, or 'sample'):\n"
    "click to capture the mouse and look around, W/A/S/D or the arrow keys to walk,\n"
    "Shift to run, PageUp/PageDown for the model's viewpoints, Home for the first,\n"
    "H headlight, F12 screenshot, Tab overlay, F1 keys, Esc releases the mouse (twice: quit).\n\n"
    "  --size WxH            window size (default 1280x720)\n"
    "  --no-vsync            draw as fast as possible (for measuring frame rates)\n"
    "  --cpu                 use the CPU renderer (lavapipe) even if a GPU exists\n"
    "  --msaa N              multisampling samples (1: off); default 4 on a GPU, 1 on lavapipe,\n"
    "                        which also leaves out anisotropic filtering there to keep 60 fps\n"
    "  --per-pixel-lighting  light per pixel on lavapipe too (it lights per vertex there, like\n"
    "                        VRML97 browsers, on faces cut small enough for it)\n"
    "  --speed-scale K       walk K times the model's NavigationInfo speed\n"
    "  --replay SCRIPT       play a scripted walk at a fixed 1/60 s per frame (README: Replay scripts)\n"
    "  --trace OUT.csv       write frame,x,y,z,yaw_deg,pitch_deg for every simulated frame\n"
    "  --screenshot-dir DIR  where F12 screenshots go (default: the current folder)\n"
    "  --no-overlay          start with the overlay hidden\n\n"
    "With Vulkan validation on (PW_VALIDATION=1, or a Debug build) any validation message\n"
    "fails the command (exit 1) when the window closes.\n";

int runWalk(Args& args) {
  walk::WalkOptions options;
  const auto sizeText = args.value("--size");
  const auto replayPath = args.value("--replay");
  const auto tracePath = args.value("--trace");
  const auto speedText = args.value("--speed-scale");
  const auto msaaText = args.value("--msaa");
  const auto screenshotDir = args.value("--screenshot-dir");
  options.vsync = !args.flag("--no-vsync");
  options.forceCpu = args.flag("--cpu");
  options.perPixelLighting = args.flag("--per-pixel-lighting");
  options.showOverlay = !args.flag("--no-overlay");
  const std::vector<std::string> positionals = args.positionals();
  if (auto finished = args.finish(); !finished) return fail(finished.message());
  if (positionals.size() != 1) return fail("walk takes one model; see photowalk walk --help");
  if (sizeText) {
    auto size = parseSize(*sizeText, "--size");
    if (!size) return fail(size.message());
    options.width = size->first;
    options.height = size->second;
  }
  if (msaaText) {
    auto n = parsePositiveInt(*msaaText, "--msaa");
    if (!n) return fail(n.message());
    options.msaaSamples = *n;  // the renderer names the counts the device has
  }
  if (speedText) {
    auto k = parseNumber(*speedText, "--speed-scale");
    if (!k) return fail(k.message());
    if (*k <= 0 || *k > 1000) return fail("--speed-scale must be between 0 and 1000");
    options.speedScale = *k;
  }
  if (replayPath) {
    auto replay = walk::readReplay(*replayPath);
    if (!replay) return fail(replay.message());
    options.replay = std::move(*replay);
  }
  if (tracePath) options.tracePath = *tracePath;
  if (screenshotDir) options.screenshotDir = *screenshotDir;

  std::vector<std::string> warnings;
  auto scene = engine::loadModel(positionals[0], &warnings);
  for (const std::string& w : warnings) printWarning(w);
  if (!scene) return fail(scene.message());
  options.title = "photowalk - " + (scene->title.empty() ? positionals[0] : scene->title);

  auto report = walk::runWalkWindow(*scene, options);
  if (!report) return fail(report.message());
  std::printf("walk: %ld frames drawn, %ld simulated; frame time median %.2f ms (%.1f fps), mean %.2f ms; %s, %dx MSAA, %s, %s\n",
              report->framesDrawn, report->framesSimulated, report->medianFrameMs,
              report->medianFrameMs > 0 ? 1000.0 / report->medianFrameMs : 0.0, report->meanFrameMs,
              report->deviceName.c_str(), report->msaaSamples,
              report->anisotropicFiltering ? "anisotropic filtering" : "trilinear filtering",
              report->perVertexLighting ? "lit per vertex" : "lit per pixel");
  return kExitOk;
}

}  // namespace

PW_COMMAND(walk, "walk", "walk through a model in a window (mouse look, WASD, viewpoints)", kUsage, runWalk);

}  // namespace pw::editor
