// base/staging.h: files that appear together, and what killed runs leave removed.
#include <signal.h>
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
