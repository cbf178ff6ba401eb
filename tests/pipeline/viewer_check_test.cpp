// What `photowalk build` writes, checked by other implementations: the .wrl loads in
// view3dscene (Castle Game Engine's viewer) without warnings and its "Photo" viewpoint
// (the first viewpoint, where view3dscene starts) looks like photowalk's own render of it; the .glb passes the Khronos glTF-Validator.
// Each check skips where its tool is not installed (scripts/install-deps.sh --with-extras,
// scripts/install-tools.sh).

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "tests/support/run_command.h"

namespace pw::editor {
namespace {
namespace fs = std::filesystem;

using test::CommandRun;
test::CommandRun shell(const std::string& command) { return test::runCommand(command); }

bool onPath(const std::string& program) { return shell("command -v " + program).exitCode == 0; }

class BuiltModel : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::path(PW_BINARY_DIR) / "test-output" / "built_model";
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "home");
    const CommandRun built = shell(std::string(PW_PHOTOWALK) + " build " + PW_SOURCE_DIR + "/assets/corridor.json -o " +
                                   (dir_ / "corridor.wrl").string() + " --gltf " + (dir_ / "corridor.glb").string() +
                                   " --px-per-m 60");
    ASSERT_EQ(built.exitCode, 0) << built.output;
  }
  static fs::path dir_;
};
fs::path BuiltModel::dir_;

TEST_F(BuiltModel, LoadsInView3dsceneAndItsPhotoViewMatchesOurs) {
  if (!onPath("view3dscene") || !onPath("xvfb-run")) GTEST_SKIP() << "view3dscene or xvfb-run is not installed";
  const fs::path shot = dir_ / "view3dscene.png", ours = dir_ / "photowalk.png";
  const fs::path log = dir_ / "home" / ".config" / "view3dscene" / "view3dscene.log";
  const CommandRun viewer = shell("HOME='" + (dir_ / "home").string() + "' xvfb-run -a -s '-screen 0 1280x1024x24' view3dscene '" +
                                  (dir_ / "corridor.wrl").string() + "' --geometry 640x360 --screenshot 0 '" +
                                  shot.string() + "'");
  ASSERT_EQ(viewer.exitCode, 0) << viewer.output;
  std::ifstream logFile(log);
  std::string line;
  while (std::getline(logFile, line)) {
    if (line.rfind("Warning", 0) == 0 && line.find("OnInitialize") == std::string::npos) ADD_FAILURE() << line;
  }
  // Validation on: render exits non-zero on any validation message.
  const CommandRun rendered = shell("PW_VALIDATION=1 " + std::string(PW_PHOTOWALK) + " render " +
                                    (dir_ / "corridor.wrl").string() + " --viewpoint Photo --size 640x360 -o " +
                                    ours.string());
  ASSERT_EQ(rendered.exitCode, 0) << rendered.output;
  const cv::Mat a = cv::imread(shot.string()), b = cv::imread(ours.string());
  ASSERT_FALSE(a.empty());
  ASSERT_EQ(a.size(), b.size());
  // Mean colour within 12/255 per channel; the photo-lit model fills the frame in both.
  const cv::Scalar ma = cv::mean(a), mb = cv::mean(b);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(ma[c], mb[c], 12.0) << "channel " << c;
  cv::Mat ga, gb;
  cv::extractChannel(a, ga, 1);
  cv::extractChannel(b, gb, 1);
  const double coveredA = cv::countNonZero(ga > 8) / double(a.total()), coveredB = cv::countNonZero(gb > 8) / double(b.total());
  EXPECT_NEAR(coveredA, coveredB, 0.03);
  std::printf("[viewer] view3dscene mean %.1f %.1f %.1f, photowalk %.1f %.1f %.1f; covered %.3f vs %.3f\n", ma[2], ma[1],
              ma[0], mb[2], mb[1], mb[0], coveredA, coveredB);
}

TEST_F(BuiltModel, GlbPassesTheKhronosValidator) {
  const fs::path tools = fs::path(PW_SOURCE_DIR) / "tools";
  if (!onPath("node") || !fs::exists(tools / "node_modules" / "gltf-validator")) {
    GTEST_SKIP() << "node or tools/node_modules/gltf-validator is missing (scripts/install-tools.sh)";
  }
  const CommandRun run = shell("node '" + (tools / "validate-gltf.mjs").string() + "' '" + (dir_ / "corridor.glb").string() + "'");
  EXPECT_EQ(run.exitCode, 0) << run.output;
  std::printf("[validator] %s", run.output.c_str());
}

}  // namespace
}  // namespace pw::editor
