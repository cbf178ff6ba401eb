// The editor's measure tool (issue 25, part 2), end to end under an X server (xvfb-run) on
// lavapipe: on corridor_b's exact corners, M and two clicks at P5 and P6 measure the floor
// across the corridor (its true width), Shift at the second click from P5 towards P7 the
// height above P5 (its true height); each with a ±; undo and redo take them away and
// back; a saved copy carries them and `photowalk measure` reads the same values from it;
// a name typed into the list is kept and undone; a click beside a corner snaps onto it.
// Validation on (PW_VALIDATION=1).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/edit/edit_run.h"
#include "tests/support/groundtruth.h"

namespace pw::edit::test {
namespace {
namespace fs = std::filesystem;
using pw::test::CommandRun;

constexpr int kWidth = 1280, kHeight = 1000;  // the 3D preview hidden (P): the whole panel in view

class Measure : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::path(PW_BINARY_DIR) / "test-output" / "edit_measure";
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    const groundtruth::GroundTruth truth = groundtruth::loadGroundTruth("corridor_b");
    fs::copy_file(truth.image, dir_ / "corridor_b.png");
    fs::copy_file(truth.shot, dir_ / "corridor_b.json");
  }
  void SetUp() override {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no X display (run under xvfb-run)";
    setenv("PW_VALIDATION", "1", 1);
  }
  std::vector<Row> edit(const std::string& name, const std::string& script, const std::string& file = "corridor_b.json") {
    const fs::path scriptPath = dir_ / (name + ".replay"), tracePath = dir_ / (name + ".jsonl");
    std::ofstream(scriptPath) << "0 key P down\n0 key P up\n" << script;
    fs::remove(tracePath);
    const CommandRun run = photowalk("edit " + (dir_ / file).string() + " --size " + std::to_string(kWidth) +
                                     "x" + std::to_string(kHeight) + " --no-vsync --replay " + scriptPath.string() +
                                     " --trace " + tracePath.string());
    EXPECT_EQ(run.exitCode, 0) << run.output;
    return readTrace(tracePath);
  }
  static fs::path dir_;
};
fs::path Measure::dir_;

TEST_F(Measure, AFloorDistanceAndAHeightWithTheirPlusMinusKeptUndoneAndSaved) {
  const groundtruth::GroundTruth truth = groundtruth::loadGroundTruth("corridor_b");
  const auto first = edit("layout", "2 quit\n");
  ASSERT_GE(first.size(), 2u);
  const Row& r = first.back();
  ASSERT_EQ(r.corners.size(), 8u);
  const glm::dvec2 p5 = r.toWindow(r.corners[4]), p6 = r.toWindow(r.corners[5]), p7 = r.toWindow(r.corners[6]);
  const glm::dvec2 p1 = r.toWindow(r.corners[0]), p2 = r.toWindow(r.corners[1]);

  Script s;
  s.key(3, "M").at(4, "key LEFT_ALT down");  // Alt: the points exactly where clicked, not snapped
  s.click(5, p5).click(10, p6);  // a distance: across the floor at the near corners
  s.click(16, p5);               // a height: Shift held at the second click, towards P7
  s.at(19, "key LEFT_SHIFT down").move(20, p7 + glm::dvec2(25, 0)).at(21, "capture measuring.png");
  s.at(22, "mouse left down").at(23, "mouse left up").at(25, "key LEFT_SHIFT up");
  s.at(28, "capture measured.png");
  s.ctrlKey(30, "Z");            // undo the height
  s.ctrlKey(34, "Z", true);      // redo it
  s.click(38, p1).click(42, p2);  // on the far wall: its top edge, the corridor's width again
  s.at(46, "key LEFT_ALT up").at(48, "save-copy measured.json").at(50, "quit");
  const auto rows = edit("measure", s.str());
  ASSERT_GE(rows.size(), 50u);

  const auto objects = [&](size_t frame) { return rows.at(frame).raw.at("objects"); };
  EXPECT_TRUE(rows.at(4).raw.at("measuring").at("active").get<bool>());
  ASSERT_EQ(objects(14).size(), 1u) << objects(14).dump();
  const nlohmann::json width = objects(14)[0];
  EXPECT_EQ(width.at("quantity"), "distance");
  EXPECT_NEAR(width.at("value_m").get<double>(), truth.widthM, 1e-6 * truth.widthM) << width.dump();
  EXPECT_GT(width.at("sigma_m").get<double>(), 0.0);
  ASSERT_EQ(objects(27).size(), 2u) << objects(27).dump();
  const nlohmann::json height = objects(27)[1];
  EXPECT_EQ(height.at("quantity"), "height");
  // B2 is the cursor's nearest point on the vertical through A2 (25 px beside P7): P7's height.
  EXPECT_NEAR(height.at("value_m").get<double>(), truth.heightM, 1e-6 * truth.heightM) << height.dump();
  EXPECT_GT(height.at("sigma_m").get<double>(), 0.0);
  // The corners did not move; undo takes the height away, redo brings it back.
  EXPECT_EQ(rows.at(27).corners, r.corners);
  EXPECT_EQ(objects(33).size(), 1u) << objects(33).dump();
  EXPECT_EQ(objects(37).size(), 2u) << objects(37).dump();
  EXPECT_TRUE(rows.at(37).dirty);
  ASSERT_EQ(objects(47).size(), 3u) << objects(47).dump();
  EXPECT_NEAR(objects(47)[2].at("value_m").get<double>(), truth.widthM, 1e-6 * truth.widthM) << objects(47).dump();

  // The saved copy carries the points and measurements; measure reads the same values.
  const fs::path saved = dir_ / "measured.json";
  ASSERT_TRUE(fs::exists(saved));
  const nlohmann::json doc = nlohmann::json::parse(std::ifstream(saved));
  ASSERT_EQ(doc.at("points").size(), 6u) << doc.dump();
  EXPECT_EQ(doc.at("points")[0].at("on"), "floor");
  EXPECT_EQ(doc.at("points")[3].at("on"), "above:A2");
  EXPECT_EQ(doc.at("points")[4].at("on"), "wall:far");
  ASSERT_EQ(doc.at("measurements").size(), 3u);
  const CommandRun measured = photowalk("measure " + saved.string());
  ASSERT_EQ(measured.exitCode, 0) << measured.output;
  const nlohmann::json out = nlohmann::json::parse(measured.output);
  ASSERT_EQ(out.at("objects").size(), 3u) << out.dump();
  EXPECT_NEAR(out["objects"][0].at("value_m").get<double>(), width.at("value_m").get<double>(), 1e-9);
  EXPECT_NEAR(out["objects"][1].at("value_m").get<double>(), height.at("value_m").get<double>(), 1e-9);

  // Named in the list: typed into its field, kept on Enter (one undo step), saved, and
  // measure's JSON says it.
  const auto& widgets = rows.at(47).raw.at("camera").at("widgets");
  ASSERT_TRUE(widgets.contains("name 1")) << widgets.dump();
  Script n;
  n.click(3, widgets["name 1"]).at(6, "type door_width").key(8, "ENTER");
  n.at(12, "save-copy named.json");
  n.ctrlKey(14, "Z");
  // Without Alt a click snaps: 5 px beside the far wall's corner P3 (on the screen), the
  // point goes onto the corner.
  const glm::dvec2 p3 = r.toWindow(r.corners[2]);
  n.key(20, "M").click(22, p3 + glm::dvec2(4, -3)).at(28, "quit");
  const auto named = edit("name", n.str(), "measured.json");
  ASSERT_GE(named.size(), 28u);
  const auto& from = named.at(27).raw.at("measuring").at("from_px");
  ASSERT_TRUE(from.is_array()) << named.at(27).raw.at("measuring").dump();
  const glm::dvec2 snapped(from[0].get<double>(), from[1].get<double>());
  std::printf("a click 5 screen px (%.1f photo px) from P3 snapped %.2f px from it\n", 5.0 / r.scale,
              glm::length(snapped - r.corners[2]));
  EXPECT_LT(glm::length(snapped - r.corners[2]), 0.75);
  EXPECT_EQ(named.at(11).raw.at("objects")[0].at("name"), "door_width") << named.at(11).raw.at("objects").dump();
  EXPECT_EQ(named.at(17).raw.at("objects")[0].at("name"), "") << "undone";
  const CommandRun readBack = photowalk("measure " + (dir_ / "named.json").string());
  ASSERT_EQ(readBack.exitCode, 0) << readBack.output;
  EXPECT_EQ(nlohmann::json::parse(readBack.output).at("objects")[0].at("name"), "door_width");
}

}  // namespace
}  // namespace pw::edit::test
