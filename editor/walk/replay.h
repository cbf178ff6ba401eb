// The walkthrough's replay scripts: the shell's events (editor/app/replay.h: key,
// mouse, resize, capture, quit, ...) and the walk's own:
//   90 viewpoint 2         go to the second viewpoint, counting from 1 as render does
// README "Replay scripts and traces" shows a whole script.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "base/result.h"
#include "editor/app/replay.h"

namespace pw::walk {

// `viewpoint N`: ModeEvent::value holds one (N from 1).
struct ViewpointEvent {
  int number = 1;
};

// The walk's own event kinds, for app::parseReplay.
std::vector<app::ReplayVerb> replayVerbs();

// Parses a walk's replay script (app::parseReplay with the walk's verbs): events sorted
// by frame, errors with file:line and what was expected, paths relative to the script.
Result<std::vector<app::ReplayEvent>> parseReplay(const std::string& text, const std::string& nameForErrors,
                                                  const std::filesystem::path& baseDir);
Result<std::vector<app::ReplayEvent>> readReplay(const std::filesystem::path& path);

}  // namespace pw::walk
