// Files that appear together or not at all: a model and its textures are written into
// a hidden folder beside their destination and moved into place only once every one
// of them is whole. A failed or killed run leaves the previous files as they were; the
// folder of a killed run (its process gone) is removed by the next run that writes
// there, finishing or undoing the renames it was killed among. Standard library and
// POSIX (a process's id from /proc, a file's inode from stat).
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "base/result.h"

namespace pw {

// This process's id, as text ("12345").
std::string processIdText();

// Whether the process PID ("12345") still runs: false once it has exited, even while
// it waits, a zombie, for its parent to collect it.
bool processRuns(const std::string& pid);

// Removes the entries of `folder` named PREFIX + PID + "-..." (or PREFIX + PID + "."...)
// whose process no longer runs: what a killed run of this program left. With a
// `marker`, the names are PREFIX + anything + MARKER + PID + ... (".frame_" and
// ".tmp-": every frame's temporary file).
void removeStaleTemporaries(const std::filesystem::path& folder, const std::string& prefix,
                            const std::string& marker = "");

// What killed runs writing `output` left beside it: the staging folders of a model
// (".NAME.photowalk-PID-N"), single-file temporaries (".STEM.tmp-PID-N.EXT"), a pending
// glTF (".STEM.pending-PID.EXT") and a partial video (".STEM.partial-PID.EXT"). A
// command calls it as it starts, so that a run killed early still finds them gone
// and a run that gets that far leaves only its own.
void removeLeftoversOf(const std::filesystem::path& output);

class StagedFiles {
 public:
  // A fresh hidden folder ".NAME.photowalk-PID-RANDOM" in `destination` (which must
  // exist), after removing those of killed runs.
  static Result<StagedFiles> create(const std::filesystem::path& destination, const std::string& name);

  StagedFiles(StagedFiles&& other) noexcept;
  StagedFiles& operator=(StagedFiles&&) = delete;
  StagedFiles(const StagedFiles&) = delete;
  ~StagedFiles();  // removes the folder and whatever is still in it

  // Where to write the file that will be `destination/fileName`.
  std::filesystem::path pathFor(const std::string& fileName) const { return folder_ / fileName; }

  // Moves the files into the destination in this order (the file that names the
  // others last), each by one rename, holding a lock (a hidden folder named after the
  // last file) so that two writers of one model do not interleave: the last wins
  // whole. A file missing from the folder is an error and nothing is moved. Then
  // removes the files `replaced` gives (called under the lock, so that it sees the
  // model that is there now): the previous model's that the new one no longer names.
  //
  // The renames are not one step, so the caller names files that differ from the
  // previous model's by names of their own (a file is replaced in place only by the
  // same bytes), and a journal in the folder says what is being moved: when this
  // process is killed among the renames, the next run (create, removeLeftoversOf)
  // removes the files it moved in if the last one never arrived, or the `replaced`
  // ones if it did. Either way one model, whole, and nothing of the other.
  Status commit(const std::vector<std::string>& fileNames,
                const std::function<std::vector<std::string>()>& replaced = nullptr);

 private:
  StagedFiles(std::filesystem::path destination, std::filesystem::path folder)
      : destination_(std::move(destination)), folder_(std::move(folder)) {}
  std::filesystem::path destination_, folder_;
};

}  // namespace pw
