// `photowalk walk`: the app shell's window (editor/app/shell.h) with the walkthrough
// (walk_mode.h) as its one mode, at a fixed simulation step of 1/60 s.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "base/result.h"
#include "editor/app/replay.h"
#include "engine/scene/scene.h"

namespace pw::walk {

struct WalkOptions {
  int width = 1280;
  int height = 720;
  bool vsync = true;
  bool forceCpu = false;
  int msaaSamples = 0;  // 0: the renderer's interactive default (4 on GPUs, 1 on lavapipe)
  bool perPixelLighting = false;  // true: also on lavapipe, at its cost
  double speedScale = 1.0;
  std::string title = "photowalk";
  std::optional<std::vector<app::ReplayEvent>> replay;  // set: deterministic, input ignored (readReplay)
  std::optional<std::filesystem::path> tracePath;       // CSV, one row per simulated frame
  std::filesystem::path screenshotDir = ".";            // F12
  bool showOverlay = true;
};

struct WalkReport {
  long framesDrawn = 0;
  long framesSimulated = 0;
  double meanFrameMs = 0;    // wall-clock per drawn frame
  double medianFrameMs = 0;
  size_t validationMessages = 0;
  std::string deviceName;
  int msaaSamples = 0;
  bool anisotropicFiltering = false;
  bool perVertexLighting = false;
};

// Opens the window and walks until it is closed (or the replay quits). Errors: no
// display, no Vulkan device that can present, a replay capture that cannot be written.
Result<WalkReport> runWalkWindow(const engine::Scene& scene, const WalkOptions& options);

}  // namespace pw::walk
