// The editor's files, as its state (the code is EditMode's, in files_ui.cpp): the file
// browser for Open, Save As and Export, the recent files, autosave and the recovery
// of what a crash left, and the question asked before unsaved edits would be lost.
#pragma once

#include <array>
#include <filesystem>
#include <future>
#include <map>
#include <optional>
#include <string>

#include "editor/edit/autosave.h"
#include "editor/edit/canvas.h"
#include "editor/edit/file_browser.h"
#include "metrology/shot.h"

namespace pw::edit {

enum class BrowserPurpose { kOpen, kSaveAs, kExportVrml, kExportGltf, kExportPage };

// `save-as FILE.json`, `export FILE.wrl|FILE.glb`: the replay events that do what the
// browser's Save As and Export do, to FILE (relative to the script).
struct SaveAsEvent {
  std::filesystem::path path;
};
struct ExportEvent {
  std::filesystem::path path;
};

struct EditFiles {
  RecentFiles recent;
  Autosave autosave;

  // The browser, while it is up.
  std::optional<FileBrowser> browser;
  BrowserPurpose purpose = BrowserPurpose::kOpen;
  std::array<char, 512> name{};  // the file name field (and the file selected)
  std::string browserError;

  // Unsaved edits would be lost: the Save / Discard / Cancel question is up, before
  // opening `open` (set) or closing the window (unset).
  struct Unsaved {
    std::optional<std::filesystem::path> open;
  };
  std::optional<Unsaved> unsaved;

  // A crash's state found beside the file just opened: the Recover / Discard question.
  std::optional<metrology::Shot> recovered;
  bool closing = false;  // the window goes: nothing more is autosaved

  // An export being written off the UI thread (a model's textures take seconds to cut
  // and encode): its file and its outcome.
  struct Export {
    std::filesystem::path path;
    std::future<Status> done;
  };
  std::optional<Export> exporting;

  // The dialog's buttons and entries as last drawn, by name (the trace's, for tests
  // to click).
  std::map<std::string, WindowRect> buttons;
  int buttonsFrame = -1;  // the ImGui frame they are of
};

}  // namespace pw::edit
