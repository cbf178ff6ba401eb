#include "base/staging.h"

#include "base/atomic_file.h"

#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <random>
#include <thread>
#include <sstream>

namespace pw {
namespace fs = std::filesystem;

std::string processIdText() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self", ec);  // "/proc/self" -> "12345"
  return ec ? std::string("0") : self.filename().string();
}

bool processRuns(const std::string& pid) {
  // /proc/PID/stat: "PID (COMM) STATE ...". A process killed but not yet reaped (its
  // parent gone too, as `timeout -s KILL` leaves it) is a zombie: it writes nothing more.
  std::ifstream stat(fs::path("/proc") / pid / "stat");
  std::string line;
  if (!stat || !std::getline(stat, line)) return false;
  const size_t close = line.rfind(')');
  if (close == std::string::npos || close + 2 >= line.size()) return true;  // unreadable: assume it runs
  const char state = line[close + 2];
  return state != 'Z' && state != 'X' && state != 'x';
}

namespace {

// In a staging folder: what its commit is moving, written before the first rename.
//   last ID NAME   the file that names the others, moved last
//   new ID NAME    a file moved in under a name nothing had
//   old ID NAME    a file of the previous model, removed once `last` is in place
// ID tells one file from another put under its name since: its inode (which a rename
// keeps, but a file made after another was removed may reuse), size and modification
// time ("INODE:SIZE:NS").
constexpr const char* kJournal = ".photowalk-journal";

std::string identityOf(const fs::path& path) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return "-";
  return std::to_string(st.st_ino) + ":" + std::to_string(st.st_size) + ":" +
         std::to_string(static_cast<long long>(st.st_mtim.tv_sec) * 1000000000LL + st.st_mtim.tv_nsec);
}

struct JournalEntry {
  std::string kind, name, id;
};

// Removes `destination/name` if it is still the file it was, not one another run has
// put there since.
void removeIfSame(const fs::path& destination, const JournalEntry& entry) {
  if (entry.id == "-" || identityOf(destination / entry.name) != entry.id) return;
  std::error_code ec;
  fs::remove(destination / entry.name, ec);
}

// A run killed among its renames: when its last file arrived, the model it names is
// whole and the previous one's leftovers go; otherwise the files it moved in go.
void settleKilledCommit(const fs::path& destination, const fs::path& folder) {
  std::ifstream in(folder / kJournal);
  std::vector<JournalEntry> entries;
  for (JournalEntry e; in >> e.kind >> e.id && in.get() == ' ' && std::getline(in, e.name);) entries.push_back(e);
  if (entries.empty() || entries.front().kind != "last") return;  // killed before its renames
  const bool arrived = identityOf(destination / entries.front().name) == entries.front().id;
  for (const JournalEntry& e : entries) {
    if (e.kind == (arrived ? "old" : "new")) removeIfSame(destination, e);
  }
}

}  // namespace

void removeStaleTemporaries(const fs::path& folder, const std::string& prefix, const std::string& marker) {
  std::error_code ec;
  const fs::path where = folder.empty() ? fs::path(".") : folder;
  for (fs::directory_iterator it(where, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) continue;
    size_t start = prefix.size();
    if (!marker.empty()) {
      const size_t at = name.find(marker, prefix.size());
      if (at == std::string::npos) continue;
      start = at + marker.size();
    }
    size_t digits = start;
    while (digits < name.size() && name[digits] >= '0' && name[digits] <= '9') ++digits;
    if (digits == start || digits == name.size() || (name[digits] != '-' && name[digits] != '.')) continue;
    const std::string pid = name.substr(start, digits - start);
    if (pid == processIdText() || processRuns(pid)) continue;  // still running
    std::error_code removeEc;
    if (fs::is_regular_file(it->path() / kJournal, removeEc)) settleKilledCommit(where, it->path());
    fs::remove_all(it->path(), removeEc);
  }
}

void removeLeftoversOf(const fs::path& output) {
  const fs::path folder = output.parent_path();
  const std::string name = output.filename().string(), stem = output.stem().string();
  for (const std::string& prefix :
       {"." + name + ".photowalk-", "." + stem + ".tmp-", "." + stem + ".pending-", "." + stem + ".partial-"}) {
    removeStaleTemporaries(folder, prefix);
  }
  // The commit lock of a run killed during its renames (named after its process; an
  // unnamed one may be a live writer's, just made: CommitLock takes those over later).
  std::error_code ec;
  const fs::path lock = (folder.empty() ? fs::path(".") : folder) / ("." + name + ".photowalk-lock");
  bool named = false, holderRuns = false;
  for (fs::directory_iterator it(lock, ec), end; !ec && it != end; it.increment(ec)) {
    named = true;
    holderRuns = holderRuns || processRuns(it->path().filename().string());
  }
  if (named && !holderRuns) fs::remove_all(lock, ec);
}

Result<StagedFiles> StagedFiles::create(const fs::path& destination, const std::string& name) {
  const fs::path where = destination.empty() ? fs::path(".") : destination;
  std::error_code existsEc;
  if (!fs::exists(where, existsEc)) return makeError("the folder " + where.string() + " does not exist");
  const std::string prefix = "." + name + ".photowalk-";
  removeStaleTemporaries(where, prefix);
  static thread_local std::mt19937_64 rng{std::random_device{}()};
  for (int attempt = 0; attempt < 8; ++attempt) {
    std::ostringstream folderName;
    folderName << prefix << processIdText() << "-" << std::hex << (rng() & 0xffffff);
    const fs::path folder = where / folderName.str();
    std::error_code ec;
    if (fs::create_directory(folder, ec)) return StagedFiles(where, folder);
    if (ec) return makeError(where.string() + ": cannot write here: " + ec.message());
  }
  return makeError(where.string() + ": cannot make a temporary folder");
}

StagedFiles::StagedFiles(StagedFiles&& other) noexcept
    : destination_(std::move(other.destination_)), folder_(std::move(other.folder_)) {
  other.folder_.clear();
}

StagedFiles::~StagedFiles() {
  if (folder_.empty()) return;
  std::error_code ec;
  fs::remove_all(folder_, ec);
}

namespace {

// One commit at a time into one destination under one name: the lock is a folder
// (mkdir is atomic) holding an empty file named after its process. A lock whose
// process is gone (killed during its renames) is taken over.
class CommitLock {
 public:
  static Result<CommitLock> acquire(const fs::path& destination, const std::string& name) {
    const fs::path lock = destination / ("." + name + ".photowalk-lock");
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (std::chrono::steady_clock::now() < deadline) {
      std::error_code ec;
      if (fs::create_directory(lock, ec)) {
        std::ofstream(lock / processIdText()).close();
        return CommitLock(lock);
      }
      if (ec) return makeError(destination.string() + ": cannot write here: " + ec.message());
      // Held: by a process that still runs? (A lock just made may not name it yet.)
      bool holderRuns = false, named = false;
      for (fs::directory_iterator it(lock, ec), end; !ec && it != end; it.increment(ec)) {
        named = true;
        holderRuns = holderRuns || processRuns(it->path().filename().string());
      }
      std::error_code timeEc;
      const auto age = fs::file_time_type::clock::now() - fs::last_write_time(lock, timeEc);
      if (!timeEc && !holderRuns && (named || age > std::chrono::seconds(2))) {
        fs::remove_all(lock, ec);  // its process was killed
        continue;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return makeError((destination / name).string() + ": another photowalk has been writing it for 30 s; nothing was written");
  }
  CommitLock(CommitLock&& other) noexcept : path_(std::move(other.path_)) { other.path_.clear(); }
  CommitLock(const CommitLock&) = delete;
  CommitLock& operator=(const CommitLock&) = delete;
  CommitLock& operator=(CommitLock&&) = delete;
  ~CommitLock() {
    if (path_.empty()) return;
    std::error_code ec;
    fs::remove_all(path_, ec);
  }

 private:
  explicit CommitLock(fs::path path) : path_(std::move(path)) {}
  fs::path path_;
};

}  // namespace

Status StagedFiles::commit(const std::vector<std::string>& fileNames,
                           const std::function<std::vector<std::string>()>& replaced) {
  std::error_code ec;
  for (const std::string& name : fileNames) {
    if (!fs::is_regular_file(folder_ / name, ec)) return makeError((destination_ / name).string() + ": nothing was written");
    // What would make a rename fail half-way through, seen before the first one.
    if (fs::is_directory(destination_ / name, ec)) {
      return makeError((destination_ / name).string() + ": cannot write: Is a directory");
    }
  }
  if (fileNames.empty()) return {};
  // Two writers of one model: each moves all its files in while it holds the lock, so
  // the last one wins whole, never a mix of both.
  auto lock = CommitLock::acquire(destination_, fileNames.back());
  if (!lock) return lock.error();
  std::vector<JournalEntry> entries{{"last", fileNames.back(), identityOf(folder_ / fileNames.back())}};
  for (const std::string& name : fileNames) {
    if (!fs::exists(fs::symlink_status(destination_ / name, ec))) entries.push_back({"new", name, identityOf(folder_ / name)});
  }
  for (const std::string& name : replaced ? replaced() : std::vector<std::string>{}) {
    const std::string id = identityOf(destination_ / name);
    if (id != "-" && std::find(fileNames.begin(), fileNames.end(), name) == fileNames.end()) {
      entries.push_back({"old", name, id});
    }
  }
  std::ostringstream journal;
  for (const JournalEntry& e : entries) journal << e.kind << " " << e.id << " " << e.name << "\n";
  if (Status written = writeFileAtomic(folder_ / kJournal, journal.str()); !written) {
    return makeError((destination_ / fileNames.back()).string() + ": " + written.message());
  }
  const auto removeAll = [&](const char* kind) {
    for (const JournalEntry& e : entries) {
      if (e.kind == kind) removeIfSame(destination_, e);
    }
  };
  for (const std::string& name : fileNames) {
    fs::rename(folder_ / name, destination_ / name, ec);
    if (ec) {
      removeAll("new");  // what this commit moved in so far: the previous model stays whole
      return makeError((destination_ / name).string() + ": cannot write: " + ec.message());
    }
  }
  removeAll("old");
  return {};
}

}  // namespace pw
