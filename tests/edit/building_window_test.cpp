// Building mode end to end under an X server (xvfb-run) on lavapipe: `photowalk edit
// LAYOUT.json` driven by replay scripts; the trace's "building" and "plan_to_window"
// fields, the saved layout and the captures are checked. Validation is on
// (PW_VALIDATION=1): edit exits non-zero on any validation message.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "base/atomic_file.h"
#include "engine/scene/image.h"
#include "tests/edit/edit_run.h"
#include "tests/support/groundtruth.h"

namespace pw::edit::test {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;
using pw::test::CommandRun;

constexpr int kWidth = 960, kHeight = 600;  // the plan is the left 672 x 600

glm::dvec2 vec2(const json& a) { return {a.at(0).get<double>(), a.at(1).get<double>()}; }

struct PlanView {
  double scale = 0;
  glm::dvec2 offset{0.0};
  glm::dvec2 toWindow(const glm::dvec2& p) const { return offset + scale * p; }
};

PlanView planView(const Row& row) {
  const json& t = row.raw.at("plan_to_window");
  return {t.at("scale").get<double>(), vec2(t.at("offset"))};
}

class Building : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::path(PW_BINARY_DIR) / "test-output" / "edit_building";
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    // Two ground-truth corridors: a hall 3.0 x 14.5 m and a wing 2.4 x 9.5 m, placed apart.
    for (const char* name : {"corridor_b", "corridor_a"}) {
      const groundtruth::GroundTruth truth = groundtruth::loadGroundTruth(name);
      fs::copy_file(truth.image, dir_ / truth.image.filename());
      fs::copy_file(truth.shot, dir_ / truth.shot.filename());
    }
  }
  void SetUp() override {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no X display (run under xvfb-run)";
    setenv("PW_VALIDATION", "1", 1);
  }

  static fs::path layoutCopy(const std::string& name) {
    const fs::path path = dir_ / (name + ".json");
    std::ofstream(path) << R"({"title": "two corridors", "corridors": [
      {"name": "hall", "shot": "corridor_b.json", "position": [0, 0, 0], "rotation_deg": 0, "colour": "blue"},
      {"name": "wing", "shot": "corridor_a.json", "position": [8, 0, 2], "rotation_deg": 0}]})";
    return path;
  }

  std::vector<Row> edit(const std::string& name, const fs::path& file, const std::string& script) {
    const fs::path scriptPath = dir_ / (name + ".replay"), tracePath = dir_ / (name + ".jsonl");
    std::ofstream(scriptPath) << script;
    fs::remove(tracePath);
    const CommandRun run = photowalk("edit " + file.string() + " --size " + std::to_string(kWidth) + "x" +
                                     std::to_string(kHeight) + " --no-vsync --replay " + scriptPath.string() +
                                     " --trace " + tracePath.string());
    EXPECT_EQ(run.exitCode, 0) << run.output;
    return readTrace(tracePath);
  }

  static fs::path dir_;
};
fs::path Building::dir_;

TEST_F(Building, DraggingTheWingToTheHallsFarEndAttachesItThereSavesAndWalksTheWholeBuilding) {
  const fs::path layout = layoutCopy("snap");
  // First where the plan lies and where the corridors stand.
  const auto probe = edit("snap-probe", layout, "1 capture plan_open.png\n2 quit\n");
  ASSERT_GE(probe.size(), 2u);
  const Row& first = probe.back();
  EXPECT_EQ(first.mode, "building");
  ASSERT_TRUE(first.raw.at("building").is_object());
  const json& corridors = first.raw["building"].at("corridors");
  ASSERT_EQ(corridors.size(), 2u);
  EXPECT_EQ(corridors[1]["name"], "wing");
  EXPECT_TRUE(corridors[1]["attach"].is_null());
  const glm::dvec2 hallSize = vec2(corridors[0]["size_m"]), wingNear = vec2(corridors[1]["position"]);
  EXPECT_NEAR(hallSize.x, 3.0, 0.05);
  EXPECT_NEAR(hallSize.y, 14.5, 0.3);
  EXPECT_NEAR(wingNear.x, 8, 1e-9);
  EXPECT_NEAR(wingNear.y, 2, 1e-9);
  const PlanView view = planView(first);
  ASSERT_GT(view.scale, 5);

  // Grab the wing 2 m into it and carry its near end to 0.12 m short of the hall's far
  // wall, 0.1 m off its centre line; capture while it snaps; release; save; walk.
  const glm::dvec2 target(0.1, -hallSize.y + 0.12);
  const glm::dvec2 grab = view.toWindow(wingNear + glm::dvec2(0, -2));
  const glm::dvec2 by = view.scale * (target - wingNear);
  Script s;
  s.move(2, grab).at(3, "mouse left down");
  for (int i = 1; i <= 6; ++i) s.move(3 + i, grab + by * (i / 6.0));
  s.at(10, "capture plan_snapping.png").at(11, "mouse left up");
  s.ctrlKey(13, "S").key(14, "F").at(15, "preview-wait").at(15, "capture plan_attached.png");  // saved, then the whole building fitted
  s.key(17, "W").at(25, "capture building_walk.png");
  // The wing's entrance, inside the second corridor (a glide of 30 frames).
  s.at(26, "viewpoint 5").at(62, "capture building_wing.png");
  s.key(66, "ESCAPE").at(70, "quit");
  const auto rows = edit("snap", layout, s.str());
  ASSERT_GE(rows.size(), 70u);

  // While dragging near the far wall, the trace says what it snaps to.
  const json& snapping = rows[9].raw.at("building");
  ASSERT_TRUE(snapping.at("snap").is_object()) << snapping.dump();
  EXPECT_EQ(snapping["snap"]["to"], "hall");
  EXPECT_EQ(snapping["snap"]["side"], "far");
  // Released: the wing is attached at the far end, its near end on the far wall's centre.
  const json& attached = rows[12].raw.at("building");
  const json& wing = attached.at("corridors").at(1);
  ASSERT_TRUE(wing.at("attach").is_object()) << attached.dump();
  EXPECT_EQ(wing["attach"]["to"], "hall");
  EXPECT_EQ(wing["attach"]["side"], "far");
  EXPECT_NEAR(wing["attach"]["offset_m"].get<double>(), 0.0, 1e-9);
  EXPECT_NEAR(vec2(wing["position"]).x, 0.0, 1e-9);
  EXPECT_NEAR(vec2(wing["position"]).y, -hallSize.y, 1e-9);
  EXPECT_TRUE(attached.at("dirty").get<bool>());
  EXPECT_EQ(attached.at("selected"), "wing");
  // Saved: clean, and the file says so, with the fields photowalk does not read kept.
  EXPECT_FALSE(rows[14].raw.at("building").at("dirty").get<bool>());
  auto text = readFile(layout);
  ASSERT_TRUE(text.ok()) << text.message();
  const json saved = json::parse(*text);
  EXPECT_EQ(saved["title"], "two corridors");
  EXPECT_EQ(saved["corridors"][0]["colour"], "blue");
  EXPECT_EQ(saved["corridors"][1]["shot"], "corridor_a.json");
  ASSERT_TRUE(saved["corridors"][1].contains("attach")) << *text;
  EXPECT_EQ(saved["corridors"][1]["attach"]["to"], "hall");
  EXPECT_EQ(saved["corridors"][1]["attach"]["side"], "far");
  EXPECT_NEAR(saved["corridors"][1]["attach"]["offset_m"].get<double>(), 0.0, 1e-9);
  const CommandRun built = photowalk("build --layout " + layout.string() + " -o " + (dir_ / "snap_model" / "m.wrl").string());
  EXPECT_EQ(built.exitCode, 0) << built.output;

  // W walks the building from the hall's photo camera; viewpoint 5 is inside the wing.
  for (int f = 18; f < 66; ++f) EXPECT_EQ(rows[f].mode, "walk") << "frame " << f;
  EXPECT_NEAR(rows[20].raw.at("x").get<double>(), 0.4, 0.05);  // corridor_b's camera: 0.4 m right, 5.5 m back
  EXPECT_NEAR(rows[20].raw.at("z").get<double>(), 5.5, 0.2);
  EXPECT_NEAR(rows[64].raw.at("x").get<double>(), 0.0, 0.05);
  EXPECT_NEAR(rows[64].raw.at("z").get<double>(), -hallSize.y, 0.3);
  EXPECT_EQ(rows[68].mode, "building");  // Esc comes back to the plan
  for (const char* picture : {"building_walk.png", "building_wing.png"}) {
    auto frame = engine::loadImage(dir_ / picture);
    ASSERT_TRUE(frame.ok()) << frame.message();
    int lo = 255, hi = 0;
    for (int y = 0; y < frame->height; y += 7) {
      for (int x = 0; x < frame->width; x += 7) {
        lo = std::min(lo, int(frame->pixel(x, y)[1]));
        hi = std::max(hi, int(frame->pixel(x, y)[1]));
      }
    }
    EXPECT_GT(hi - lo, 60) << picture << ": the model, not a blank";
  }
}

TEST_F(Building, EachShotIsEditedInTheEditorKeepsItsChangesAcrossSwitchesAndChangesThePlan) {
  const fs::path layout = layoutCopy("shots");
  fs::copy_file(dir_ / "corridor_a.json", dir_ / "wing_before.json", fs::copy_options::overwrite_existing);
  const std::string hallBytes = *readFile(dir_ / "corridor_b.json");
  Script s;
  s.key(2, "TAB").key(3, "TAB").key(4, "E");  // select the hall, then the wing; edit the wing's shot
  // In the shot editor: the far wall's floor corners P3 and P4 up 5 px each (a longer wing).
  s.at(6, "key LEFT_ALT down").key(6, "3").at(6, "key LEFT_ALT up");
  for (int f = 7; f < 12; ++f) s.key(f, "UP");
  s.at(12, "key LEFT_ALT down").key(12, "4").at(12, "key LEFT_ALT up");
  for (int f = 13; f < 18; ++f) s.key(f, "UP");
  s.key(19, "B");                             // back to the plan
  s.key(24, "TAB").key(25, "E").key(28, "B");  // the hall's shot, and back
  s.key(30, "TAB").key(31, "E");              // the wing's again: as it was left
  s.key(34, "B").ctrlKey(36, "S").at(38, "quit");
  const auto rows = edit("shots", layout, s.str());
  ASSERT_GE(rows.size(), 38u);
  ASSERT_TRUE(rows[1].raw.at("building").is_object());
  const double lengthBefore = vec2(rows[1].raw["building"]["corridors"][1]["size_m"]).y;
  EXPECT_EQ(rows[3].raw["building"]["selected"], "wing");
  EXPECT_EQ(rows[5].mode, "edit");
  ASSERT_TRUE(rows[5].path.has_value());
  EXPECT_EQ(fs::path(*rows[5].path).filename(), "corridor_a.json");
  ASSERT_EQ(rows[5].corners.size(), 8u);
  const glm::dvec2 p3 = rows[5].corners[2], p4 = rows[5].corners[3];
  EXPECT_TRUE(rows[18].dirty);
  // Back in the plan: the wing is longer, and the building has unsaved changes.
  EXPECT_EQ(rows[21].mode, "building");
  const double lengthAfter = vec2(rows[21].raw["building"]["corridors"][1]["size_m"]).y;
  EXPECT_GT(lengthAfter, lengthBefore + 0.1) << lengthBefore << " -> " << lengthAfter;
  EXPECT_TRUE(rows[21].raw["building"]["dirty"].get<bool>());
  // The hall's shot in the editor, clean; then the wing's again, with its changes.
  EXPECT_EQ(rows[26].mode, "edit");
  EXPECT_EQ(fs::path(rows[26].path.value_or("")).filename(), "corridor_b.json");
  EXPECT_FALSE(rows[26].dirty);
  EXPECT_EQ(rows[32].mode, "edit");
  EXPECT_EQ(fs::path(rows[32].path.value_or("")).filename(), "corridor_a.json");
  EXPECT_TRUE(rows[32].dirty);
  ASSERT_EQ(rows[32].corners.size(), 8u);
  EXPECT_NEAR(rows[32].corners[2].y, p3.y - 5, 1e-9);
  EXPECT_NEAR(rows[32].corners[3].y, p4.y - 5, 1e-9);
  // Ctrl+S in the plan saved the wing's shot (the hall's had nothing to save).
  EXPECT_FALSE(rows[37].raw["building"]["dirty"].get<bool>());
  auto saved = readFile(dir_ / "corridor_a.json");
  ASSERT_TRUE(saved.ok());
  const json wing = json::parse(*saved);
  EXPECT_NEAR(wing["corners_px"]["P3"][1].get<double>(), p3.y - 5, 1e-9);
  EXPECT_EQ(*readFile(dir_ / "corridor_b.json"), hallBytes);
  fs::copy_file(dir_ / "wing_before.json", dir_ / "corridor_a.json", fs::copy_options::overwrite_existing);
}

TEST_F(Building, CorridorsTurnByKeyAndHandleMoveFreeWithAltAndEachDragIsOneUndoStep) {
  const fs::path layout = layoutCopy("turn");
  const auto probe = edit("turn-probe", layout, "1 quit\n");
  ASSERT_GE(probe.size(), 1u);
  const PlanView view = planView(probe.back());
  const json& corridors = probe.back().raw.at("building").at("corridors");
  const glm::dvec2 wingNear = vec2(corridors[1]["position"]), wingSize = vec2(corridors[1]["size_m"]);
  // The turn handle: 22 px beyond the far wall's centre, along the corridor (up the window at rotation 0).
  const glm::dvec2 nearPx = view.toWindow(wingNear);
  const glm::dvec2 handle = view.toWindow(wingNear + glm::dvec2(0, -wingSize.y)) + glm::dvec2(0, -22);
  const double radius = glm::length(handle - nearPx);
  Script s;
  s.key(2, "TAB").key(3, "TAB");  // the wing
  s.key(4, "R").ctrlKey(6, "Z").ctrlKey(8, "Y").ctrlKey(10, "Z");
  // The handle carried a quarter turn round the near end, to its left: +90 degrees.
  s.move(12, handle).at(13, "mouse left down");
  for (int i = 1; i <= 6; ++i) {
    const double a = glm::radians(15.0 * i);
    s.move(13 + i, nearPx + radius * glm::dvec2(-std::sin(a), -std::cos(a)));
  }
  s.at(20, "mouse left up").ctrlKey(22, "Z");
  // Moved 2 m right with Alt (no snapping), then undone.
  const glm::dvec2 grab = view.toWindow(wingNear + glm::dvec2(0, -3));
  s.at(24, "key LEFT_ALT down").move(24, grab).at(25, "mouse left down");
  for (int i = 1; i <= 4; ++i) s.move(25 + i, grab + glm::dvec2(2 * view.scale * i / 4.0, 0));
  s.at(30, "mouse left up").at(31, "key LEFT_ALT up").ctrlKey(33, "Z").at(35, "quit");
  const auto rows = edit("turn", layout, s.str());
  ASSERT_GE(rows.size(), 35u);
  const auto wing = [&](int frame) { return rows[frame].raw.at("building").at("corridors").at(1); };
  EXPECT_EQ(wing(5)["rotation_deg"].get<double>(), 90.0);  // R: a quarter turn to the left
  EXPECT_NEAR(vec2(wing(5)["position"]).x, wingNear.x, 1e-9);  // about the near end
  EXPECT_EQ(wing(7)["rotation_deg"].get<double>(), 0.0);   // undone
  EXPECT_EQ(wing(9)["rotation_deg"].get<double>(), 90.0);  // redone
  EXPECT_EQ(wing(11)["rotation_deg"].get<double>(), 0.0);
  EXPECT_NEAR(wing(17)["rotation_deg"].get<double>(), 60.0, 1e-6);  // following the handle
  EXPECT_NEAR(wing(21)["rotation_deg"].get<double>(), 90.0, 1e-6);
  EXPECT_EQ(wing(23)["rotation_deg"].get<double>(), 0.0);  // the whole drag was one step
  EXPECT_NEAR(vec2(wing(31)["position"]).x, wingNear.x + 2, 1e-9);
  EXPECT_TRUE(wing(31)["attach"].is_null());
  EXPECT_NEAR(vec2(wing(34)["position"]).x, wingNear.x, 1e-12);
  EXPECT_FALSE(rows[34].raw["building"]["dirty"].get<bool>());
}

// The wing carried 2 m right with Alt (no snapping): frames 2 to 8.
Script movedWing(const Row& probe) {
  const PlanView view = planView(probe);
  const glm::dvec2 wingNear = vec2(probe.raw.at("building").at("corridors").at(1).at("position"));
  const glm::dvec2 grab = view.toWindow(wingNear + glm::dvec2(0, -3));
  Script s;
  s.at(2, "key LEFT_ALT down").move(2, grab).at(3, "mouse left down");
  for (int i = 1; i <= 4; ++i) s.move(3 + i, grab + glm::dvec2(2 * view.scale * i / 4.0, 0));
  s.at(8, "mouse left up").at(8, "key LEFT_ALT up");
  return s;
}

const json& question(const Row& row) { return row.raw.at("question"); }

TEST_F(Building, ClosingWithUnsavedChangesAsksSaveAllDiscardOrCancelAndTheWindowStaysUntilAnswered) {
  const fs::path layout = layoutCopy("unsaved");
  const std::string before = *readFile(layout);
  const auto probe = edit("unsaved-probe", layout, "1 quit\n");
  ASSERT_GE(probe.size(), 1u);
  const double wingX = vec2(probe.back().raw.at("building").at("corridors").at(1).at("position")).x;

  // Close: the question, the window still there; Esc cancels it, the move stays.
  Script ask = movedWing(probe.back());
  ask.at(12, "close").at(20, "capture building_question.png").key(25, "ESCAPE").at(30, "quit");
  const auto asked = edit("unsaved-ask", layout, ask.str());
  ASSERT_GE(asked.size(), 30u) << "the window stays while the question is up";
  EXPECT_TRUE(question(asked[11]).is_null());
  ASSERT_TRUE(question(asked[15]).is_object()) << asked[15].raw.dump();
  EXPECT_EQ(question(asked[15])["about"], "close");
  EXPECT_EQ(question(asked[15])["files"].size(), 1u);  // the layout (no shot changed)
  const json saveAll = question(asked[21]).at("buttons").at("Save all");
  ASSERT_EQ(saveAll.size(), 4u);
  EXPECT_TRUE(question(asked[21])["buttons"].contains("Discard"));
  EXPECT_TRUE(question(asked[21])["buttons"].contains("Cancel"));
  EXPECT_TRUE(question(asked[27]).is_null());  // cancelled
  EXPECT_TRUE(asked[27].raw.at("building").at("dirty").get<bool>());
  EXPECT_NEAR(vec2(asked[27].raw["building"]["corridors"][1]["position"]).x, wingX + 2, 1e-9);
  EXPECT_EQ(*readFile(layout), before);
  EXPECT_TRUE(fs::exists(dir_ / "building_question.png"));

  // Close, then a click on Save all: the layout is written and the run ends there.
  Script save = movedWing(probe.back());
  save.at(12, "close").move(20, {double(saveAll[0]) + 0.5 * double(saveAll[2]), double(saveAll[1]) + 0.5 * double(saveAll[3])});
  save.at(21, "mouse left down").at(22, "mouse left up").at(60, "quit");
  const auto saved = edit("unsaved-save", layout, save.str());
  ASSERT_FALSE(saved.empty());
  EXPECT_LT(saved.back().frame, 30) << "Save all closes the window";
  auto text = readFile(layout);
  ASSERT_TRUE(text.ok());
  const json file = json::parse(*text);
  EXPECT_NEAR(file["corridors"][1]["position"][0].get<double>(), wingX + 2, 1e-9) << *text;
  EXPECT_EQ(file["title"], "two corridors");
}

// Issue 23's finding: `photowalk edit corridor_a.png`, then close, switched to an empty
// building plan asking "Unsaved changes in the building". A photo never edited has
// nothing to lose: the window closes at once, from the editor, asking nothing.
TEST_F(Building, ClosingAPhotoNeverEditedClosesAtOnceAskingNothing) {
  const auto rows = edit("photo-close", dir_ / "corridor_a.png", "3 close\n40 quit\n");
  ASSERT_GE(rows.size(), 3u);
  EXPECT_LT(rows.size(), 10u) << "the window stayed after close";
  for (const Row& row : rows) {
    EXPECT_EQ(row.mode, "edit") << row.raw.dump();
    EXPECT_TRUE(!row.raw.contains("question") || row.raw.at("question").is_null()) << row.raw.dump();
  }
}

TEST_F(Building, ClosingFromTheShotEditorAsksAboutTheWholeBuildingAndDiscardWritesNothing) {
  const fs::path layout = layoutCopy("discard");
  const std::string before = *readFile(layout);
  const std::string wingBytes = *readFile(dir_ / "corridor_a.json");
  const auto probe = edit("discard-probe", layout, "1 quit\n");
  ASSERT_GE(probe.size(), 1u);
  // The wing moved, then its shot opened in the shot editor (clean: only the layout is
  // unsaved); the close there asks in the plan; D discards and closes.
  Script s = movedWing(probe.back());
  s.key(10, "E").at(14, "close").key(20, "D").at(60, "quit");
  const auto rows = edit("discard", layout, s.str());
  ASSERT_GE(rows.size(), 20u);
  EXPECT_EQ(rows[12].mode, "edit");
  EXPECT_EQ(rows[16].mode, "building");
  ASSERT_TRUE(question(rows[16]).is_object()) << rows[16].raw.dump();
  EXPECT_EQ(question(rows[16])["about"], "close");
  EXPECT_LT(rows.back().frame, 30) << "Discard closes the window";
  EXPECT_EQ(*readFile(layout), before);
  EXPECT_EQ(*readFile(dir_ / "corridor_a.json"), wingBytes);
}

TEST_F(Building, ClosingWithAnotherShotEditedInTheEditorAsksOnceForItAndTheBuilding) {
  const fs::path layout = layoutCopy("other-close");
  const fs::path other = dir_ / "other_shot.json";
  fs::copy_file(dir_ / "corridor_a.json", other, fs::copy_options::overwrite_existing);
  const auto probe = edit("other-close-probe", layout, "1 quit\n");
  ASSERT_GE(probe.size(), 1u);
  const double wingX = vec2(probe.back().raw.at("building").at("corridors").at(1).at("position")).x;
  // The wing moved; in the shot editor another shot file (not the building's) opened
  // and its P3 nudged up 2 px; the close asks about both in the plan; S saves both.
  Script s = movedWing(probe.back());
  s.key(10, "E").at(12, "drop " + other.string());
  s.at(14, "key LEFT_ALT down").key(14, "3").at(14, "key LEFT_ALT up").key(15, "UP").key(16, "UP");
  s.at(18, "close").key(24, "S").at(60, "quit");
  const auto rows = edit("other-close", layout, s.str());
  ASSERT_GE(rows.size(), 24u);
  EXPECT_EQ(rows[17].mode, "edit");
  EXPECT_EQ(fs::path(rows[17].path.value_or("")), other);
  EXPECT_TRUE(rows[17].dirty);
  const double p3y = rows[17].corners.at(2).y;
  EXPECT_EQ(rows[20].mode, "building");
  ASSERT_TRUE(question(rows[20]).is_object()) << rows[20].raw.dump();
  EXPECT_EQ(question(rows[20])["files"].size(), 2u) << question(rows[20]).dump();
  EXPECT_LT(rows.back().frame, 30) << "Save all closes the window";
  const json file = json::parse(*readFile(layout));
  EXPECT_NEAR(file["corridors"][1]["position"][0].get<double>(), wingX + 2, 1e-9);
  const json shot = json::parse(*readFile(other));
  EXPECT_NEAR(shot["corners_px"]["P3"][1].get<double>(), p3y, 1e-9);
}

TEST_F(Building, ALayoutDroppedOverUnsavedChangesAsksFirst) {
  const fs::path layout = layoutCopy("drop-over"), other = layoutCopy("drop-other");
  const auto probe = edit("drop-over-probe", layout, "1 quit\n");
  ASSERT_GE(probe.size(), 1u);
  Script s = movedWing(probe.back());
  s.at(12, "drop " + other.string()).key(20, "ESCAPE").at(24, "drop " + other.string()).key(30, "D").at(34, "quit");
  const auto rows = edit("drop-over", layout, s.str());
  ASSERT_GE(rows.size(), 34u);
  ASSERT_TRUE(question(rows[15]).is_object());
  EXPECT_EQ(question(rows[15])["about"], "open");
  EXPECT_EQ(fs::path(rows[22].raw.at("building").at("path").get<std::string>()), layout);  // Cancel: still this one
  EXPECT_TRUE(rows[22].raw["building"]["dirty"].get<bool>());
  EXPECT_EQ(fs::path(rows[32].raw.at("building").at("path").get<std::string>()), other);  // Discard: the other
  EXPECT_FALSE(rows[32].raw["building"]["dirty"].get<bool>());
}

TEST_F(Building, ThePreviewPaneShowsTheWholeBuildingRebuiltWhenAnEditIsReleasedNotDuringTheDrag) {
  const fs::path layout = layoutCopy("pane");
  const auto probe = edit("pane-probe", layout, "1 quit\n");
  ASSERT_GE(probe.size(), 1u);
  const PlanView view = planView(probe.back());
  const json& corridors = probe.back().raw.at("building").at("corridors");
  const glm::dvec2 hallSize = vec2(corridors[0]["size_m"]), wingNear = vec2(corridors[1]["position"]);
  // The first model, then the wing dragged onto the hall's far wall (as above), released.
  const glm::dvec2 target(0.1, -hallSize.y + 0.12);
  const glm::dvec2 grab = view.toWindow(wingNear + glm::dvec2(0, -2));
  const glm::dvec2 by = view.scale * (target - wingNear);
  Script s;
  s.at(1, "preview-wait").at(2, "capture pane_before.png").move(2, grab).at(3, "mouse left down");
  for (int i = 1; i <= 6; ++i) s.move(3 + i, grab + by * (i / 6.0));
  s.at(11, "mouse left up").at(13, "preview-wait").at(13, "capture pane_after.png");
  // A left drag over the pane orbits it (the plan stays as it is).
  const json paneRect = probe.back().raw.at("preview").at("rect");
  const glm::dvec2 paneCentre{double(paneRect[0]) + 0.5 * double(paneRect[2]), double(paneRect[1]) + 0.5 * double(paneRect[3])};
  s.move(15, paneCentre).at(16, "mouse left down").move(17, paneCentre + glm::dvec2(40, 10)).at(18, "mouse left up");
  s.at(20, "quit");
  const auto rows = edit("pane", layout, s.str());
  ASSERT_GE(rows.size(), 20u);
  const auto preview = [&](int frame) { return rows[frame].raw.at("preview"); };
  EXPECT_TRUE(preview(1)["model"].get<bool>()) << preview(1).dump();
  EXPECT_TRUE(preview(1)["current"].get<bool>());
  EXPECT_TRUE(preview(1)["error"].is_null()) << preview(1).dump();
  for (int f = 4; f <= 10; ++f) {  // dragging: nothing is built
    EXPECT_FALSE(preview(f)["current"].get<bool>()) << "frame " << f;
    EXPECT_FALSE(preview(f)["building"].get<bool>()) << "frame " << f;
  }
  EXPECT_TRUE(rows[11].raw["building"]["corridors"][1]["attach"].is_object());
  EXPECT_TRUE(preview(11)["building"].get<bool>());  // released: the new layout is being built
  EXPECT_TRUE(preview(13)["current"].get<bool>()) << preview(13).dump();
  EXPECT_FALSE(preview(13)["building"].get<bool>());
  EXPECT_EQ(preview(13)["camera"], "overview");
  EXPECT_EQ(preview(19)["camera"], "orbit");
  EXPECT_EQ(rows[19].raw["building"]["corridors"], rows[13].raw["building"]["corridors"]);
  EXPECT_TRUE(preview(19)["current"].get<bool>());

  // The pane in the capture: the model, not its background (0.13, 0.14, 0.16).
  const json rect = preview(13).at("rect");
  ASSERT_GT(rect[2].get<double>(), 100);
  ASSERT_GT(rect[3].get<double>(), 100);
  for (const char* picture : {"pane_before.png", "pane_after.png"}) {
    auto frame = engine::loadImage(dir_ / picture);
    ASSERT_TRUE(frame.ok()) << frame.message();
    int model = 0, all = 0;
    for (int y = int(rect[1]) + 20; y < int(rect[1]) + int(rect[3]) - 2; y += 3) {
      for (int x = int(rect[0]) + 2; x < int(rect[0]) + int(rect[2]) - 2; x += 3) {
        const auto p = frame->pixel(x, y);
        ++all;
        if (std::abs(int(p[0]) - 33) + std::abs(int(p[1]) - 36) + std::abs(int(p[2]) - 41) > 24) ++model;
      }
    }
    EXPECT_GT(model, all / 10) << picture << ": " << model << " of " << all << " pixels are the model's";
  }
}

TEST_F(Building, ALayoutThatCannotBeReadOrBuiltIsAMessageAndTheWindowStays) {
  const fs::path bad = dir_ / "bad.json";
  std::ofstream(bad) << R"({"corridors": [{"name": "hall", "shot": "corridor_b.json"},
    {"name": "wing", "shot": "corridor_a.json", "attach": {"to": "nowhere"}}]})";
  const auto refused = edit("bad", bad, "3 quit\n");
  ASSERT_GE(refused.size(), 3u);
  EXPECT_EQ(refused[2].mode, "building");
  EXPECT_TRUE(refused[2].raw.at("building").is_null());
  // An offset beyond the hall's far wall: it opens, and says why it cannot be built.
  const fs::path wide = dir_ / "wide.json";
  std::ofstream(wide) << R"({"corridors": [{"name": "hall", "shot": "corridor_b.json"},
    {"name": "wing", "shot": "corridor_a.json", "attach": {"to": "hall", "side": "far", "offset_m": 9}},
    {"name": "lost", "shot": "missing.json", "position": [-8, 0, 0]}]})";
  const auto opened = edit("wide", wide, "2 key W down\n2 key W up\n4 quit\n");
  ASSERT_GE(opened.size(), 4u);
  const json& building = opened[3].raw.at("building");
  ASSERT_TRUE(building.is_object());
  EXPECT_EQ(opened[3].mode, "building");  // W refused: no walk
  ASSERT_TRUE(building.at("error").is_string());
  EXPECT_NE(building["error"].get<std::string>().find("wing"), std::string::npos) << building["error"];
  EXPECT_EQ(building["corridors"].size(), 3u);
}

TEST_F(Building, ALayoutDroppedOnTheShotEditorOpensThePlan) {
  const fs::path layout = layoutCopy("dropped");
  const auto rows = edit("dropped", "", "2 drop " + layout.string() + "\n5 quit\n");
  ASSERT_GE(rows.size(), 5u);
  EXPECT_EQ(rows[1].mode, "edit");
  EXPECT_EQ(rows[4].mode, "building");
  ASSERT_TRUE(rows[4].raw.at("building").is_object());
  EXPECT_EQ(rows[4].raw["building"]["corridors"].size(), 2u);
}

}  // namespace
}  // namespace pw::edit::test
