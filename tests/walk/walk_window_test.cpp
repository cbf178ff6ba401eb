// photowalk walk, end to end under an X server (xvfb-run) on lavapipe: scripted walks
// through the sample corridor model, checked through the trace and the captures.
// Validation is on (PW_VALIDATION=1): walk exits non-zero on any validation message.

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/scene/image.h"
#include "tests/walk/walk_run.h"

namespace pw::walk {
namespace {
namespace fs = std::filesystem;

using test::CommandRun;

// The sample corridor (assets/corridor.json: 4.0 x 3.5 x 19.0 m, camera 1.7 m high,
// 6 m before the near corners), built once for all tests.
class Walk : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::path(PW_BINARY_DIR) / "test-output" / "walk";
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    const CommandRun built = photowalk("build " + std::string(PW_SOURCE_DIR) + "/assets/corridor.json -o " +
                                (dir_ / "corridor.wrl").string() + " --px-per-m 40");
    ASSERT_EQ(built.exitCode, 0) << built.output;
  }
  void SetUp() override {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no X display (run under xvfb-run)";
    setenv("PW_VALIDATION", "1", 1);
  }

  // Runs `script` and returns the trace.
  std::vector<TraceRow> walk(const std::string& name, const std::string& script, const std::string& extra = "") {
    const fs::path scriptPath = dir_ / (name + ".replay"), tracePath = dir_ / (name + ".csv");
    std::ofstream(scriptPath) << script;
    const CommandRun run = photowalk("walk " + (dir_ / "corridor.wrl").string() + " --size 320x180 --no-vsync --replay " +
                              scriptPath.string() + " --trace " + tracePath.string() + " " + extra);
    EXPECT_EQ(run.exitCode, 0) << run.output;
    return readTrace(tracePath);
  }

  static fs::path dir_;
};
fs::path Walk::dir_;

TEST_F(Walk, ForwardMovesAlongTheCorridorAtTheSetSpeed) {
  const auto rows = walk("forward", "0 key W down\n120 key W up\n130 quit\n");
  ASSERT_GE(rows.size(), 130u);
  // NavigationInfo speed 1.4 m/s, 120 steps of 1/60 s: 2.8 m towards -Z.
  EXPECT_NEAR(rows[119].z - (rows[0].z + 1.4 / 60), -2.8, 1e-3);  // rows[0] is after the first step
  EXPECT_NEAR(rows[125].z, rows[119].z, 1e-9);  // stops when the key is released
  for (const TraceRow& r : rows) {
    EXPECT_NEAR(r.y, 1.7, 1e-4) << "frame " << r.frame;  // eye at the avatar height
    EXPECT_NEAR(r.x, rows[0].x, 1e-6);
  }
}

TEST_F(Walk, FarWallStopsTheWalkerAtTheAvatarRadiusEvenAtTenTimesTheSpeed) {
  for (const char* scale : {"1", "10"}) {
    const auto rows = walk(std::string("wall_") + scale, "0 key LEFT_SHIFT down\n0 key W down\n900 quit\n",
                           std::string("--speed-scale ") + scale);
    ASSERT_GE(rows.size(), 900u);
    double nearest = 0;
    for (const TraceRow& r : rows) nearest = std::min(nearest, r.z);
    // The far wall is at z = -19; the avatar radius is 0.25 m.
    EXPECT_GE(nearest, -19.0 + 0.25 - 1e-3) << "speed scale " << scale;
    if (std::string(scale) == "10") {
      EXPECT_NEAR(rows.back().z, -19.0 + 0.25, 0.01);
    }
  }
}

TEST_F(Walk, ViewpointChangeLandsExactlyOnTheViewpoint) {
  const auto rows = walk("viewpoint", "10 viewpoint 3\n60 quit\n");
  ASSERT_GE(rows.size(), 60u);
  // Viewpoint 3, "Far end looking back": (0, 1.7, -18) facing +Z (yaw 180).
  const TraceRow& r = rows[55];
  EXPECT_NEAR(r.x, 0.0, 1e-5);
  EXPECT_NEAR(r.y, 1.7, 1e-5);
  EXPECT_NEAR(r.z, -18.0, 1e-5);
  EXPECT_NEAR(std::abs(r.yawDeg), 180.0, 1e-3);
}

TEST_F(Walk, CapturedFrameMatchesTheHeadlessRender) {
  walk("capture", "0 viewpoint 2\n40 capture entrance.png\n41 quit\n");
  const fs::path headless = dir_ / "entrance_headless.png";
  const CommandRun rendered = photowalk("render " + (dir_ / "corridor.wrl").string() + " --viewpoint 2 --size 320x180 -o " +
                                 headless.string());
  ASSERT_EQ(rendered.exitCode, 0) << rendered.output;
  auto a = engine::loadImage(dir_ / "entrance.png");
  auto b = engine::loadImage(headless);
  ASSERT_TRUE(a.ok() && b.ok());
  ASSERT_EQ(a->width, b->width);
  ASSERT_EQ(a->height, b->height);
  // Same renderer, same camera: at most 2/255 per channel on 99% of the pixels.
  size_t close = 0;
  for (size_t i = 0; i < a->rgba.size(); i += 4) {
    bool within = true;
    for (int c = 0; c < 3; ++c) within &= std::abs(int(a->rgba[i + c]) - int(b->rgba[i + c])) <= 2;
    close += within;
  }
  EXPECT_GE(static_cast<double>(close) / (a->rgba.size() / 4), 0.99);
}

TEST_F(Walk, ResizeDuringTheReplayGivesFramesOfTheNewSize) {
  walk("resize", "0 key W down\n5 resize 400 240\n10 capture small.png\n15 resize 480 320\n20 capture large.png\n25 quit\n");
  auto small = engine::loadImage(dir_ / "small.png");
  auto large = engine::loadImage(dir_ / "large.png");
  ASSERT_TRUE(small.ok()) << small.message();
  ASSERT_TRUE(large.ok()) << large.message();
  EXPECT_EQ(small->width, 400);
  EXPECT_EQ(small->height, 240);
  EXPECT_EQ(large->width, 480);
  EXPECT_EQ(large->height, 320);
}

TEST_F(Walk, BadReplayIsAOneLineError) {
  const fs::path scriptPath = dir_ / "bad.replay";
  std::ofstream(scriptPath) << "5 key W down\n7 fly up\n";
  const CommandRun run = photowalk("walk " + (dir_ / "corridor.wrl").string() + " --replay " + scriptPath.string());
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.output.find("bad.replay:2:"), std::string::npos) << run.output;
}

}  // namespace
}  // namespace pw::walk
