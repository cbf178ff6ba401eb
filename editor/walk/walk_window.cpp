#include "editor/walk/walk_window.h"

#include "editor/app/shell.h"
#include "editor/walk/walk_mode.h"

namespace pw::walk {

Result<WalkReport> runWalkWindow(const engine::Scene& scene, const WalkOptions& options) {
  app::ShellOptions shellOptions;
  shellOptions.window = {options.width, options.height, options.title};
  shellOptions.vsync = options.vsync;
  shellOptions.renderer.forceCpu = options.forceCpu;
  shellOptions.renderer.profile = engine::RenderProfile::kInteractive;
  shellOptions.renderer.msaaSamples = options.msaaSamples;
  if (options.perPixelLighting) shellOptions.renderer.perVertexLighting = false;
  shellOptions.replay = options.replay;
  shellOptions.tracePath = options.tracePath;
  shellOptions.traceFormat = app::TraceFormat::kCsv;
  auto shell = app::Shell::create(shellOptions);
  if (!shell) return shell.error();

  WalkModeOptions walkOptions;
  walkOptions.speedScale = options.speedScale;
  walkOptions.screenshotDir = options.screenshotDir;
  walkOptions.showOverlay = options.showOverlay;
  WalkMode walk(scene, walkOptions);
  PW_TRY((*shell)->addMode(walk));
  auto run = (*shell)->run(walk.name());
  if (!run) return run.error();

  const engine::Renderer& renderer = (*shell)->renderer();
  WalkReport report;
  report.framesDrawn = run->framesDrawn;
  report.framesSimulated = run->framesSimulated;
  report.meanFrameMs = run->meanFrameMs;
  report.medianFrameMs = run->medianFrameMs;
  report.validationMessages = run->validationMessages;
  report.deviceName = renderer.deviceName();
  report.msaaSamples = renderer.msaaSamples();
  report.anisotropicFiltering = renderer.anisotropicFiltering();
  report.perVertexLighting = renderer.perVertexLighting();
  return report;
}

}  // namespace pw::walk
