// `photowalk edit`: the app shell's window with the editor (edit_mode.h) and the walk
// of its model (model_walk.h) as its two modes, starting in the editor.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "base/result.h"
#include "editor/app/replay.h"
#include "editor/edit/document.h"

namespace pw::edit {

struct EditWindowOptions {
  std::optional<std::filesystem::path> file;  // a photo or a shot file; none: the editor opens empty
  OpenOptions open;
  int width = 1280;
  int height = 720;
  bool vsync = true;
  bool forceCpu = false;
  std::optional<std::vector<app::ReplayEvent>> replay;  // readEditReplay; set: deterministic, input ignored
  std::optional<std::filesystem::path> tracePath;       // JSON lines, one per simulated frame
};

struct EditReport {
  long framesDrawn = 0;
  long framesSimulated = 0;
  double medianFrameMs = 0;
  std::string deviceName;
};

// The editor's replay scripts: the shell's events, the editor's (save-copy FILE) and the
// walk's (viewpoint N). Errors: file:line and what was expected.
Result<std::vector<app::ReplayEvent>> readEditReplay(const std::filesystem::path& path);

// Opens the window and edits until it is closed (or the replay ends). A file that
// cannot be opened is a message in the window, not an error. Errors: no display, no
// Vulkan device that can present, a replay event that cannot be done, and, with
// validation on, any validation message.
Result<EditReport> runEditWindow(const EditWindowOptions& options);

}  // namespace pw::edit
