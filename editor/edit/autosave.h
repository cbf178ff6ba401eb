// Autosave while a document has unsaved edits, and the recovery of what a crash left.
// The side file of a shot saved at DIR/NAME.json is DIR/.NAME.json.autosave (hidden,
// beside it): a shot file itself, what Save would write, written atomically. Save and
// a clean close remove it; a crash (or a replay's `quit`) leaves it, and opening the
// same file again offers its state back (recoverableShot). No window: tested headless
// (tests/edit/file_browser_test.cpp).
#pragma once

#include <filesystem>
#include <optional>

#include "base/result.h"
#include "editor/edit/document.h"

namespace pw::edit {

std::filesystem::path autosavePath(const std::filesystem::path& savePath);

class Autosave {
 public:
  static constexpr double kIntervalS = 3.0;  // simulated time, so that replays are deterministic

  // One simulation step of `stepS` seconds with `doc` open (null: none). Every
  // kIntervalS, writes the side file of doc->path() when the document has unsaved
  // edits it does not hold yet, and removes the side file it wrote once there are none
  // (undone, or saved). Errors: the side file cannot be written (tried again at the
  // next interval; said once until a write succeeds).
  Status step(const Document* doc, double stepS);
  // Removes the side file of `savePath` (after a save, a discard, a clean close) and
  // forgets what was written.
  void remove(const std::filesystem::path& savePath);
  // Forgets what was written without removing anything (another file was opened).
  void reset();
  // The document path whose side file this wrote, while it is there.
  const std::optional<std::filesystem::path>& writtenFor() const { return writtenFor_; }

 private:
  double sinceS_ = 0;
  std::optional<metrology::Shot> writtenShot_;
  std::optional<std::filesystem::path> writtenFor_;
  bool failing_ = false;
};

// The state in the side file of `doc` when there is one that differs from the
// document's shot: what a crash left (the document's photo, with the camera and the
// corners of the side file). nullopt: no side file, or one equal to the document.
// Errors: a side file that cannot be read, or that is of another photo (it is left in
// place; the message says where it is).
Result<std::optional<metrology::Shot>> recoverableShot(const Document& doc);

}  // namespace pw::edit
