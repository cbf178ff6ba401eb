// base/staging.h: files that appear together, and what killed runs leave removed.
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "base/staging.h"

namespace pw {
namespace {
namespace fs = std::filesystem;

std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class StagingTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("pw_staging_test_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  size_t entries() const { return static_cast<size_t>(std::distance(fs::directory_iterator(dir_), fs::directory_iterator())); }
  fs::path dir_;
};

TEST_F(StagingTest, FilesAppearOnlyOnCommitAndTheFolderGoes) {
  std::ofstream(dir_ / "m.wrl") << "old model";
  {
    auto staged = StagedFiles::create(dir_, "m.wrl");
    ASSERT_TRUE(staged) << staged.message();
    std::ofstream(staged->pathFor("m_a.png")) << "texture";
    std::ofstream(staged->pathFor("m.wrl")) << "new model";
    EXPECT_EQ(readText(dir_ / "m.wrl"), "old model");
    EXPECT_FALSE(fs::exists(dir_ / "m_a.png"));
    ASSERT_TRUE(staged->commit({"m_a.png", "m.wrl"}));
  }
  EXPECT_EQ(readText(dir_ / "m.wrl"), "new model");
  EXPECT_EQ(readText(dir_ / "m_a.png"), "texture");
  EXPECT_EQ(entries(), 2u);  // no staging folder, no lock
}

TEST_F(StagingTest, AFailedWriteLeavesNothing) {
  {
    auto staged = StagedFiles::create(dir_, "m.wrl");
    ASSERT_TRUE(staged);
    std::ofstream(staged->pathFor("m_a.png")) << "texture";
    EXPECT_FALSE(staged->commit({"m_a.png", "m.wrl"}));  // the model was never written
  }
  EXPECT_EQ(entries(), 0u);
}

TEST_F(StagingTest, WhatAKilledRunLeftIsRemoved) {
  // A process id that cannot run (above Linux's pid_max), and this process's own.
  fs::create_directories(dir_ / ".m.wrl.photowalk-999999999-abc");
  fs::create_directories(dir_ / (".m.wrl.photowalk-" + processIdText() + "-def"));
  std::ofstream(dir_ / ".m_a.tmp-999999999-12.png") << "half";
  fs::create_directories(dir_ / ".m.wrl.photowalk-lock");
  std::ofstream(dir_ / ".m.wrl.photowalk-lock" / "999999999").close();
  removeStaleTemporaries(dir_, ".m_a.tmp-");
  EXPECT_FALSE(fs::exists(dir_ / ".m_a.tmp-999999999-12.png"));
  auto staged = StagedFiles::create(dir_, "m.wrl");
  ASSERT_TRUE(staged);
  EXPECT_FALSE(fs::exists(dir_ / ".m.wrl.photowalk-999999999-abc"));
  EXPECT_TRUE(fs::exists(dir_ / (".m.wrl.photowalk-" + processIdText() + "-def"))) << "a running process's is kept";
  std::ofstream(staged->pathFor("m.wrl")) << "model";
  // The lock a killed run held is taken over.
  EXPECT_TRUE(staged->commit({"m.wrl"}));
  EXPECT_FALSE(fs::exists(dir_ / ".m.wrl.photowalk-lock"));
}

TEST_F(StagingTest, ARunStartingRemovesWhatKilledRunsLeftForItsOutput) {
  // 999999999: above Linux's pid_max, so never a running process.
  fs::create_directories(dir_ / ".m.wrl.photowalk-999999999-abc" / "m_s_floor.png");
  std::ofstream(dir_ / ".m.tmp-999999999-12.wrl") << "half";
  std::ofstream(dir_ / ".m.pending-999999999.glb") << "half";
  std::ofstream(dir_ / ".m.partial-999999999.avi") << "half";
  fs::create_directories(dir_ / ".m.wrl.photowalk-lock");
  std::ofstream(dir_ / ".m.wrl.photowalk-lock" / "999999999").close();
  // Not this output's, or a running process's: kept.
  std::ofstream(dir_ / ".other.tmp-999999999-12.wrl") << "another output's";
  std::ofstream(dir_ / (".m.tmp-" + processIdText() + "-13.wrl")) << "this process's";
  std::ofstream(dir_ / ".frame_0007.tmp-999999999-1.png") << "half a frame";
  std::ofstream(dir_ / (".frame_0008.tmp-" + processIdText() + "-1.png")) << "a frame being written";
  removeLeftoversOf(dir_ / "m.wrl");
  removeStaleTemporaries(dir_, ".frame_", ".tmp-");
  std::vector<std::string> left;
  for (const auto& entry : fs::directory_iterator(dir_)) left.push_back(entry.path().filename().string());
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (std::vector<std::string>{".frame_0008.tmp-" + processIdText() + "-1.png",
                                            ".m.tmp-" + processIdText() + "-13.wrl", ".other.tmp-999999999-12.wrl"}));
  // A lock held by a running process stays.
  fs::create_directories(dir_ / ".m.wrl.photowalk-lock");
  std::ofstream(dir_ / ".m.wrl.photowalk-lock" / processIdText()).close();
  removeLeftoversOf(dir_ / "m.wrl");
  EXPECT_TRUE(fs::exists(dir_ / ".m.wrl.photowalk-lock"));
}

// A commit killed among its renames, as its journal records it: model 1 (m.wrl naming
// m_a.png) in place; model 2 (m.wrl naming m_a_2.png) staged by a process that no
// longer runs, its texture already moved in and, when `modelArrived`, its model too.
class KilledCommitTest : public StagingTest {
 protected:
  void killedAmongRenames(bool modelArrived) {
    std::ofstream(dir_ / "m.wrl") << "model 1";
    std::ofstream(dir_ / "m_a.png") << "a1";
    const fs::path staged = dir_ / ".m.wrl.photowalk-999999999-abc";
    fs::create_directories(staged);
    std::ofstream(staged / "m.wrl") << "model 2";
    std::ofstream(staged / "m_a_2.png") << "a2";
    std::ofstream(staged / ".photowalk-journal") << "last " << inode(staged / "m.wrl") << " m.wrl\n"
                                                 << "new " << inode(staged / "m_a_2.png") << " m_a_2.png\n"
                                                 << "old " << inode(dir_ / "m_a.png") << " m_a.png\n";
    fs::rename(staged / "m_a_2.png", dir_ / "m_a_2.png");
    if (modelArrived) fs::rename(staged / "m.wrl", dir_ / "m.wrl");
  }
  // As the journal identifies a file: inode, size, modification time.
  static std::string inode(const fs::path& path) {
    struct stat st {};
    EXPECT_EQ(::stat(path.c_str(), &st), 0) << path;
    return std::to_string(st.st_ino) + ":" + std::to_string(st.st_size) + ":" +
           std::to_string(static_cast<long long>(st.st_mtim.tv_sec) * 1000000000LL + st.st_mtim.tv_nsec);
  }
  std::vector<std::string> left() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
};

TEST_F(KilledCommitTest, KilledBeforeItsModelArrivedItsTexturesGo) {
  killedAmongRenames(false);
  removeLeftoversOf(dir_ / "m.wrl");
  EXPECT_EQ(left(), (std::vector<std::string>{"m.wrl", "m_a.png"}));
  EXPECT_EQ(readText(dir_ / "m.wrl"), "model 1");
  EXPECT_EQ(readText(dir_ / "m_a.png"), "a1");
}

TEST_F(KilledCommitTest, KilledAfterItsModelArrivedThePreviousTexturesGo) {
  killedAmongRenames(true);
  ASSERT_TRUE(StagedFiles::create(dir_, "m.wrl"));  // as a run starting to write it
  EXPECT_EQ(left(), (std::vector<std::string>{"m.wrl", "m_a_2.png"}));
  EXPECT_EQ(readText(dir_ / "m.wrl"), "model 2");
}

TEST_F(KilledCommitTest, AFileAnotherRunPutThereSinceStays) {
  killedAmongRenames(false);
  // Another run replaced m_a_2.png with its own (a new file: another inode).
  fs::remove(dir_ / "m_a_2.png");
  std::ofstream(dir_ / "m_a_2.png") << "another run's";
  removeLeftoversOf(dir_ / "m.wrl");
  EXPECT_EQ(readText(dir_ / "m_a_2.png"), "another run's");
}

TEST_F(StagingTest, ACommitRemovesWhatThePreviousModelNamedAndTheNewOneDoesNot) {
  std::ofstream(dir_ / "m.wrl") << "model 1";
  std::ofstream(dir_ / "m_a.png") << "a1";
  std::ofstream(dir_ / "m_b.png") << "b, kept";
  auto staged = StagedFiles::create(dir_, "m.wrl");
  ASSERT_TRUE(staged);
  std::ofstream(staged->pathFor("m_a_2.png")) << "a2";
  std::ofstream(staged->pathFor("m_b.png")) << "b, kept";
  std::ofstream(staged->pathFor("m.wrl")) << "model 2";
  bool asked = false;
  ASSERT_TRUE(staged->commit({"m_a_2.png", "m_b.png", "m.wrl"}, [&] {
    asked = true;
    EXPECT_EQ(readText(dir_ / "m.wrl"), "model 1") << "asked before the model is replaced";
    return std::vector<std::string>{"m_a.png", "m_b.png", "m_missing.png"};
  }));
  EXPECT_TRUE(asked);
  EXPECT_FALSE(fs::exists(dir_ / "m_a.png"));
  EXPECT_EQ(readText(dir_ / "m_b.png"), "b, kept") << "a file the new model names too stays";
  EXPECT_EQ(readText(dir_ / "m_a_2.png"), "a2");
}

TEST_F(StagingTest, AKilledProcessNotYetCollectedIsNotRunning) {
  // `timeout -s KILL` dies with the process it kills, which then waits, a zombie, for
  // someone to collect it: what it left must be removable at once, not after that.
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::pause();
    ::_exit(0);
  }
  const std::string pid = std::to_string(child);
  EXPECT_TRUE(processRuns(pid));
  ::kill(child, SIGKILL);
  siginfo_t info{};
  ASSERT_EQ(::waitid(P_PID, static_cast<id_t>(child), &info, WEXITED | WNOWAIT), 0);  // a zombie: not collected
  EXPECT_FALSE(processRuns(pid));
  fs::create_directories(dir_ / (".m.wrl.photowalk-" + pid + "-abc"));
  removeStaleTemporaries(dir_, ".m.wrl.photowalk-");
  EXPECT_FALSE(fs::exists(dir_ / (".m.wrl.photowalk-" + pid + "-abc")));
  ::waitpid(child, nullptr, 0);
  EXPECT_FALSE(processRuns(pid));
  EXPECT_TRUE(processRuns(processIdText()));
}

}  // namespace
}  // namespace pw
