#include "editor/edit/file_browser.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>

#include <nlohmann/json.hpp>

#include "base/atomic_file.h"

namespace pw::edit {
namespace fs = std::filesystem;

namespace {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char ch) { return std::tolower(ch); });
  return text;
}

fs::path absoluteOf(const fs::path& path) {
  std::error_code ec;
  const fs::path absolute = fs::absolute(path, ec);
  return (ec ? path : absolute).lexically_normal();
}

}  // namespace

bool matchesEndings(const std::string& fileName, const std::vector<std::string>& endings) {
  if (endings.empty()) return true;
  const std::string name = lower(fileName);
  return std::any_of(endings.begin(), endings.end(), [&](const std::string& ending) {
    return name.size() > ending.size() && name.compare(name.size() - ending.size(), ending.size(), ending) == 0;
  });
}

Result<std::vector<FolderEntry>> listFolder(const fs::path& folder, const std::vector<std::string>& endings) {
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) return makeError(folder.string() + ": not a folder");
  fs::directory_iterator it(folder, fs::directory_options::skip_permission_denied, ec);
  if (ec) return makeError(folder.string() + ": cannot be read: " + ec.message());
  std::vector<FolderEntry> folders, files;
  for (; it != fs::directory_iterator(); it.increment(ec)) {
    if (ec) return makeError(folder.string() + ": cannot be read: " + ec.message());
    const std::string name = it->path().filename().string();
    if (name.empty() || name[0] == '.') continue;
    std::error_code statError;
    if (it->is_directory(statError)) {
      folders.push_back({name, it->path(), true});
    } else if (!statError && it->is_regular_file(statError) && matchesEndings(name, endings)) {
      files.push_back({name, it->path(), false});
    }
  }
  const auto byName = [](const FolderEntry& a, const FolderEntry& b) {
    const std::string x = lower(a.name), y = lower(b.name);
    return x != y ? x < y : a.name < b.name;
  };
  std::sort(folders.begin(), folders.end(), byName);
  std::sort(files.begin(), files.end(), byName);
  folders.insert(folders.end(), files.begin(), files.end());
  return folders;
}

Status FileBrowser::enter(const fs::path& folder) {
  const fs::path absolute = absoluteOf(folder);
  auto listed = listFolder(absolute, endings_);
  if (!listed) return listed.error();
  folder_ = absolute;
  entries_ = std::move(*listed);
  return {};
}

Status FileBrowser::up() {
  const fs::path parent = folder_.parent_path();
  if (parent.empty() || parent == folder_) return {};
  return enter(parent);
}

RecentFiles RecentFiles::load(const fs::path& file) {
  RecentFiles recent;
  recent.file_ = file;
  std::error_code ec;
  if (file.empty() || !fs::exists(file, ec)) return recent;
  auto text = readFile(file);
  if (!text) {
    recent.problem_ = text.message();
    return recent;
  }
  const nlohmann::json json = nlohmann::json::parse(*text, nullptr, false);
  if (json.is_discarded() || !json.is_object() || !json.contains("recent") || !json["recent"].is_array()) {
    recent.problem_ = file.string() + ": not a recent files list ({\"recent\": [...]}); it is replaced on the next open";
    return recent;
  }
  for (const nlohmann::json& entry : json["recent"]) {
    if (entry.is_string() && recent.paths_.size() < kMaxFiles) recent.paths_.emplace_back(entry.get<std::string>());
  }
  return recent;
}

Status RecentFiles::add(const fs::path& path) {
  const fs::path absolute = absoluteOf(path);
  std::erase(paths_, absolute);
  paths_.insert(paths_.begin(), absolute);
  if (paths_.size() > kMaxFiles) paths_.resize(kMaxFiles);
  return write();
}

Status RecentFiles::remove(const fs::path& path) {
  std::erase(paths_, absoluteOf(path));
  return write();
}

Status RecentFiles::write() const {
  if (file_.empty()) return {};
  nlohmann::json list = nlohmann::json::array();
  for (const fs::path& path : paths_) list.push_back(path.string());
  std::error_code ec;
  if (file_.has_parent_path()) fs::create_directories(file_.parent_path(), ec);
  return writeFileAtomic(file_, nlohmann::json{{"recent", list}}.dump(2) + "\n");
}

fs::path defaultRecentFilesPath() {
  if (const char* own = std::getenv("PW_RECENT_FILES")) return fs::path(own);
  if (const char* config = std::getenv("XDG_CONFIG_HOME"); config && *config) {
    return fs::path(config) / "photowalk" / "recent.json";
  }
  if (const char* home = std::getenv("HOME"); home && *home) return fs::path(home) / ".config" / "photowalk" / "recent.json";
  return {};
}

}  // namespace pw::edit
