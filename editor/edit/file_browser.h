// The editor's file browser without the window: a folder's entries, filtered and
// sorted, and the recent files, kept in a small JSON file. The ImGui part is
// files_ui.cpp; this part is tested headless (tests/edit/file_browser_test.cpp).
//
//   FileBrowser browser(kOpenableEndings);
//   browser.enter("/photos");                  // folders first, then PNG/JPEG/JSON files
//   for (const FolderEntry& e : browser.entries()) ...;
//   RecentFiles recent = RecentFiles::load(defaultRecentFilesPath());
//   recent.add("/photos/hall.json");            // first in the list, written atomically
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "base/result.h"

namespace pw::edit {

// What the browser shows, as name endings (lower case, matched case-insensitively).
inline const std::vector<std::string> kOpenableEndings = {".png", ".jpg", ".jpeg", ".json"};  // photos, shots
inline const std::vector<std::string> kShotEndings = {".json"};
inline const std::vector<std::string> kModelEndings = {".wrl", ".wrl.gz", ".wrz", ".glb", ".gltf"};

// True when `fileName` ends in one of `endings` (ignoring case); every name when
// `endings` is empty.
bool matchesEndings(const std::string& fileName, const std::vector<std::string>& endings);

struct FolderEntry {
  std::string name;  // the file name
  std::filesystem::path path;
  bool folder = false;
};

// The folders and the files whose names match `endings` in `folder`: folders first,
// then files, each in name order ignoring case. Hidden entries (a name starting with
// '.', as the autosave files and the atomic writes' temporaries) are left out, and so
// are entries that cannot be examined. Errors: not a folder, not readable.
Result<std::vector<FolderEntry>> listFolder(const std::filesystem::path& folder, const std::vector<std::string>& endings);

// A browser's state: the folder shown and its entries.
class FileBrowser {
 public:
  explicit FileBrowser(std::vector<std::string> endings) : endings_(std::move(endings)) {}

  // Shows `folder` (made absolute). Errors: as listFolder; the browser then stays where it was.
  Status enter(const std::filesystem::path& folder);
  // The folder above; nothing at the root.
  Status up();
  // Lists the folder again (files come and go).
  Status refresh() { return enter(folder_); }

  const std::filesystem::path& folder() const { return folder_; }
  const std::vector<FolderEntry>& entries() const { return entries_; }
  const std::vector<std::string>& endings() const { return endings_; }

 private:
  std::vector<std::string> endings_;
  std::filesystem::path folder_;
  std::vector<FolderEntry> entries_;
};

// The files opened or saved last, newest first, kept in a JSON file
// ({"recent": ["/abs/a.json", ...]}) that is written atomically on every change.
class RecentFiles {
 public:
  static constexpr size_t kMaxFiles = 10;

  // Reads the list kept at `file`. A missing file gives an empty list; an unreadable
  // or malformed one too, with problem() saying why (it is replaced on the next add).
  // An empty `file`: a list kept in memory only.
  static RecentFiles load(const std::filesystem::path& file);

  const std::vector<std::filesystem::path>& paths() const { return paths_; }
  const std::filesystem::path& file() const { return file_; }
  const std::string& problem() const { return problem_; }

  // Puts `path` (made absolute) first, without a second entry for it, keeping
  // kMaxFiles, and writes the list (its folders created). Errors: the list cannot be
  // written (it is kept in memory all the same).
  Status add(const std::filesystem::path& path);
  // Takes `path` off the list (a file that is gone) and writes the list.
  Status remove(const std::filesystem::path& path);

 private:
  Status write() const;

  std::filesystem::path file_;
  std::vector<std::filesystem::path> paths_;
  std::string problem_;
};

// Where the recent files list is kept: $PW_RECENT_FILES when set (set but empty: in
// memory only), else $XDG_CONFIG_HOME/photowalk/recent.json, else
// $HOME/.config/photowalk/recent.json; empty (in memory only) when none is set.
std::filesystem::path defaultRecentFilesPath();

}  // namespace pw::edit
