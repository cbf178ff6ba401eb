// Replay scripts: a deterministic walk for tests and measurements.
//
// One event per line, `FRAME WHAT ...`, FRAME counting simulated frames of 1/60 s
// from 0 whatever the real frame rate; '#' starts a comment:
//   10 key W down          (key names as GLFW names them: W, A, S, D, UP, LEFT_SHIFT,
//   70 key W up             PAGE_UP, PAGE_DOWN, HOME, F12, H, TAB, ...)
//   80 mouse 120 -30       (pointer motion in pixels, as if the cursor were captured)
//   90 viewpoint 2         (go to the second viewpoint, counting from 1 as render does)
//   95 resize 800 600      (resize the window)
//  100 capture out.png     (save the frame drawn at this frame)
//  120 quit
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "base/result.h"

namespace pw::walk {

struct ReplayEvent {
  enum class Kind { kKey, kMouse, kViewpoint, kResize, kCapture, kQuit };
  int frame = 0;
  Kind kind = Kind::kQuit;
  std::string name;  // key name, or capture file
  bool down = false;  // key
  double dx = 0, dy = 0;  // mouse; resize: width, height
  int index = 0;          // viewpoint
};

// Parses a replay script; events come back sorted by frame (stable). Errors give
// file:line and what was expected. Capture paths are relative to the script.
Result<std::vector<ReplayEvent>> readReplay(const std::filesystem::path& path);
Result<std::vector<ReplayEvent>> parseReplay(const std::string& text, const std::string& nameForErrors,
                                             const std::filesystem::path& baseDir);

// GLFW's key code for a name ("W", "LEFT_SHIFT", "PAGE_UP", "F12"), -1 if unknown.
// (The codes are GLFW's, but the table lives here so that parsing needs no GLFW.)
int keyCodeFromName(const std::string& name);

}  // namespace pw::walk
