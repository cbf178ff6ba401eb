// The editor's stand-up tool (issue 25, part 3), end to end under an X server (xvfb-run)
// on lavapipe: on the random corridor with a person (tests/groundtruth: TUNE seed 0, its
// exact corners), U and a rectangle dragged around the person keep a cutout in the shot;
// undo and redo take it away and back; a rectangle running off the photo's bottom edge is
// refused with the reason and changes nothing; a name typed into the list is kept; its
// "box" stands it up as a box, undoably; the saved copy carries the cutout and `photowalk
// build` stands the person up from it, as tall as she is; O and a doorway's corners clicked
// open the wall there; a rectangle around a lamp above the horizon hangs it; a cutout the
// model cannot stand up is said left painted. Validation on (PW_VALIDATION=1).
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "metrology/measure.h"
#include "modeling/pipeline.h"
#include "tests/edit/edit_run.h"

namespace pw::edit::test {
namespace {
namespace fs = std::filesystem;
using pw::test::CommandRun;

constexpr int kWidth = 1280, kHeight = 1000;  // the 3D preview hidden (P): the whole panel in view

class StandUp : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::path(PW_BINARY_DIR) / "test-output" / "edit_stand_up";
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    const fs::path random = fs::path(PW_GROUNDTRUTH_DIR) / "random";
    fs::copy_file(random / "seed_00000.png", dir_ / "seed_00000.png");
    fs::copy_file(random / "seed_00000.json", dir_ / "seed_00000.json");
  }
  void SetUp() override {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no X display (run under xvfb-run)";
    setenv("PW_VALIDATION", "1", 1);
  }
  std::vector<Row> edit(const std::string& name, const std::string& script, std::string* output = nullptr,
                        const std::string& file = "seed_00000.json") {
    const fs::path scriptPath = dir_ / (name + ".replay"), tracePath = dir_ / (name + ".jsonl");
    std::ofstream(scriptPath) << "0 key P down\n0 key P up\n" << script;
    fs::remove(tracePath);
    const CommandRun run = photowalk("edit " + (dir_ / file).string() + " --size " + std::to_string(kWidth) + "x" +
                                     std::to_string(kHeight) + " --no-vsync --replay " + scriptPath.string() +
                                     " --trace " + tracePath.string());
    EXPECT_EQ(run.exitCode, 0) << run.output;
    if (output) *output = run.output;
    return readTrace(tracePath);
  }
  // The person in the scene, from its answers: the top of her head and her feet (photo
  // pixels), a little more than half her width in pixels, her height.
  struct Person {
    glm::dvec2 head, feet;
    double halfWidthPx = 0, heightM = 0;
    int photoHeightPx = 0;
  };
  static std::optional<Person> person() {
    const nlohmann::json truth = nlohmann::json::parse(std::ifstream(dir_ / "seed_00000.json"));
    for (const nlohmann::json& o : truth.at("objects")) {
      if (o.at("kind") != "person") continue;
      Person p;
      p.head = {o["keypoints_px"]["head_top"][0], o["keypoints_px"]["head_top"][1]};
      p.feet = {o["keypoints_px"]["feet"][0], o["keypoints_px"]["feet"][1]};
      p.heightM = o["size_m"][1];
      p.halfWidthPx = 0.7 * (p.feet.y - p.head.y) * o["size_m"][0].get<double>() / p.heightM;
      p.photoHeightPx = truth["image_size"][1];
      return p;
    }
    return std::nullopt;
  }
  // `photowalk build` of the shot file NAME.json in the test's folder into NAME.wrl: the
  // model's text ("" when the build failed, itself a failure).
  static std::string builtModel(const std::string& name) {
    const CommandRun built =
        photowalk("build " + (dir_ / (name + ".json")).string() + " -o " + (dir_ / (name + ".wrl")).string());
    EXPECT_EQ(built.exitCode, 0) << built.output;
    if (built.exitCode != 0) return "";
    std::ifstream model(dir_ / (name + ".wrl"));
    return std::string((std::istreambuf_iterator<char>(model)), std::istreambuf_iterator<char>());
  }
  static fs::path dir_;
};
fs::path StandUp::dir_;

TEST_F(StandUp, ARectangleAroundAPersonStandsHerUpUndoneRedoneNamedAndSaved) {
  const std::optional<Person> her = person();
  ASSERT_TRUE(her.has_value()) << "no person in the scene's answers";
  const glm::dvec2 head = her->head, feet = her->feet;
  const double halfWidthPx = her->halfWidthPx;
  // A person's rough rectangle around her (photo pixels): from above her head to below her feet.
  const glm::dvec2 from(feet.x - halfWidthPx, head.y - 8), to(feet.x + halfWidthPx, feet.y + 10);

  const auto first = edit("layout", "2 quit\n");
  ASSERT_GE(first.size(), 2u);
  const Row& r = first.back();
  const glm::dvec2 a = r.toWindow(from), b = r.toWindow(to);
  const glm::dvec2 bottom = r.toWindow({feet.x, her->photoHeightPx - 20.0});

  Script s;
  s.key(3, "U");
  s.drag(5, a, b - a, 6);                                // frames 5-12: the rectangle around her
  s.at(14, "capture standing.png");
  s.ctrlKey(16, "Z");                                    // undo
  s.ctrlKey(19, "Z", true);                              // redo
  s.drag(22, bottom, glm::dvec2(40, 60), 4);             // off the photo's bottom edge: refused
  s.at(30, "save-copy standing.json").at(32, "quit");
  std::string output;
  const auto rows = edit("stand_up", s.str(), &output);
  ASSERT_GE(rows.size(), 32u);
  const auto cutouts = [&](size_t frame) { return rows.at(frame).raw.at("cutouts"); };
  EXPECT_TRUE(rows.at(4).raw.at("outlining").at("active").get<bool>());
  EXPECT_TRUE(rows.at(8).raw.at("outlining").at("from_px").is_array()) << "dragging";
  ASSERT_EQ(cutouts(14).size(), 1u) << cutouts(14).dump();
  EXPECT_EQ(cutouts(14)[0].at("name"), "object 1");
  const nlohmann::json outline = cutouts(14)[0].at("outline_px");
  ASSERT_EQ(outline.size(), 4u);
  EXPECT_NEAR(outline[0][0].get<double>(), from.x, 1.0 / r.scale + 0.01) << outline.dump();
  EXPECT_NEAR(outline[2][1].get<double>(), to.y, 1.0 / r.scale + 0.01) << outline.dump();
  EXPECT_TRUE(rows.at(14).dirty);
  EXPECT_EQ(cutouts(18).size(), 0u) << "undone";
  EXPECT_EQ(cutouts(21).size(), 1u) << "redone";
  EXPECT_EQ(cutouts(29).size(), 1u) << "the rectangle off the bottom edge was kept";
  EXPECT_NE(output.find("stand up: cutout \"object 2\": it runs off the photo's bottom edge"), std::string::npos) << output;
  EXPECT_NE(output.find("stood up object 1: 1.9"), std::string::npos) << output;

  // Named in the list, kept on Enter (one undo step).
  const auto& widgets = rows.at(29).raw.at("camera").at("widgets");
  ASSERT_TRUE(widgets.contains("cutout 1")) << widgets.dump();
  ASSERT_TRUE(widgets.contains("cutout 1 box")) << widgets.dump();
  Script n;
  n.click(3, widgets["cutout 1"]).ctrlKeyHeld(5, "A").at(10, "type person").key(12, "ENTER");
  n.at(15, "save-copy named.json");
  // Stood up as a box instead (the list's "box"), undone and redone.
  n.click(18, widgets["cutout 1 box"]).at(21, "boxes-wait").at(22, "capture standing_box.png");
  n.ctrlKey(23, "Z").ctrlKey(26, "Z", true);
  n.at(29, "save-copy boxed.json").at(31, "quit");
  std::string boxOutput;
  const auto named = edit("name", n.str(), &boxOutput, "standing.json");
  ASSERT_GE(named.size(), 31u);
  EXPECT_EQ(named.at(16).raw.at("cutouts")[0].at("name"), "person") << named.at(16).raw.at("cutouts").dump();
  EXPECT_EQ(named.at(16).raw.at("cutouts")[0].at("shape"), "flat");
  EXPECT_EQ(named.at(21).raw.at("cutouts")[0].at("shape"), "box") << named.at(21).raw.at("cutouts").dump();
  // The box as fitted, drawn on the photo: its eight corners about the person's outline.
  const nlohmann::json drawn = named.at(22).raw.at("cutouts")[0];
  ASSERT_TRUE(drawn.contains("box_px")) << drawn.dump();
  ASSERT_EQ(drawn["box_px"].size(), 8u);
  for (const nlohmann::json& p : drawn["box_px"]) {
    EXPECT_GT(p[0].get<double>(), from.x - 20);
    EXPECT_LT(p[0].get<double>(), to.x + 20);
    EXPECT_GT(p[1].get<double>(), from.y - 20);
    EXPECT_LT(p[1].get<double>(), to.y + 20);
  }
  EXPECT_FALSE(named.at(16).raw.at("cutouts")[0].contains("box_px")) << "a flat cut-out has none";
  EXPECT_EQ(named.at(25).raw.at("cutouts")[0].at("shape"), "flat") << "undone";
  EXPECT_EQ(named.at(28).raw.at("cutouts")[0].at("shape"), "box") << "redone";
  EXPECT_NE(boxOutput.find("person stands as a box: "), std::string::npos) << boxOutput;
  const nlohmann::json boxed = nlohmann::json::parse(std::ifstream(dir_ / "boxed.json"));
  EXPECT_EQ(boxed.at("cutouts")[0].at("shape"), "box") << boxed.dump();

  // The saved copy stands her up in `build`: as tall as she is (1.945 m).
  const fs::path saved = dir_ / "named.json";
  ASSERT_TRUE(fs::exists(saved));
  const std::string text = builtModel("named");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(text, m, std::regex("stood up: person \\([^)]*\\), a cut-out [0-9.]+ m wide and ([0-9.]+) m high")))
      << "no 'stood up' line in the model";
  EXPECT_NEAR(std::stod(m[1]), her->heightM, 0.03);
}

// A polygon clicked around her (a stray point taken back with Backspace, closed on its
// first point) stands her up as the rectangle does; a polygon of two points is not
// closed by Enter, and Esc drops it without leaving the tool.
TEST_F(StandUp, APolygonClickedAroundAPersonStandsHerUp) {
  const std::optional<Person> her = person();
  ASSERT_TRUE(her.has_value()) << "no person in the scene's answers";
  const glm::dvec2 head = her->head, feet = her->feet;
  const double halfWidthPx = her->halfWidthPx;
  // A hexagon around her (photo pixels), as a person clicks it: above her head either
  // side, out at her shoulders, below her feet either side.
  const double shoulders = head.y + 0.25 * (feet.y - head.y);
  const std::vector<glm::dvec2> around = {{feet.x - 0.6 * halfWidthPx, head.y - 10}, {feet.x + 0.6 * halfWidthPx, head.y - 10},
                                          {feet.x + halfWidthPx, shoulders},        {feet.x + halfWidthPx, feet.y + 10},
                                          {feet.x - halfWidthPx, feet.y + 10},      {feet.x - halfWidthPx, shoulders}};

  const auto first = edit("polygon_layout", "2 quit\n");
  ASSERT_GE(first.size(), 2u);
  const Row& r = first.back();
  Script s;
  s.key(3, "U");
  s.click(5, r.toWindow(around[0])).click(8, r.toWindow(around[1])).click(11, r.toWindow(around[2]));
  s.click(14, r.toWindow(head + glm::dvec2(200, 0)));  // a stray point ...
  s.key(17, "BACKSPACE");                               // ... taken back
  s.click(19, r.toWindow(around[3])).click(22, r.toWindow(around[4])).click(25, r.toWindow(around[5]));
  s.move(27, r.toWindow(around[0]) + glm::dvec2(3, 2)).at(27, "capture standing_polygon_open.png");
  s.click(28, r.toWindow(around[0]) + glm::dvec2(3, 2));  // the first point again: closed
  s.at(32, "capture standing_polygon.png");
  s.click(34, r.toWindow(head + glm::dvec2(-150, 0))).click(37, r.toWindow(head + glm::dvec2(-100, 40)));
  s.key(41, "ENTER");   // two points: not closed
  s.key(43, "ESCAPE");  // dropped, the tool still on
  s.at(46, "quit");
  std::string output;
  const auto rows = edit("stand_up_polygon", s.str(), &output);
  ASSERT_GE(rows.size(), 46u);
  const auto outlining = [&](size_t frame) { return rows.at(frame).raw.at("outlining"); };
  EXPECT_EQ(outlining(7).at("polygon_px").size(), 1u) << outlining(7).dump();
  EXPECT_EQ(outlining(16).at("polygon_px").size(), 4u) << outlining(16).dump();
  EXPECT_EQ(outlining(18).at("polygon_px").size(), 3u) << "Backspace takes the last point back";
  EXPECT_EQ(rows.at(29).raw.at("cutouts").size(), 0u) << "not closed yet";
  const nlohmann::json cutouts = rows.at(32).raw.at("cutouts");
  ASSERT_EQ(cutouts.size(), 1u) << cutouts.dump() << output;
  const nlohmann::json outline = cutouts[0].at("outline_px");
  ASSERT_EQ(outline.size(), around.size()) << outline.dump();
  for (size_t i = 0; i < around.size(); ++i) {
    EXPECT_NEAR(outline[i][0].get<double>(), around[i].x, 1.0 / r.scale + 0.01) << i;
    EXPECT_NEAR(outline[i][1].get<double>(), around[i].y, 1.0 / r.scale + 0.01) << i;
  }
  EXPECT_TRUE(outlining(32).at("polygon_px").empty());
  EXPECT_NE(output.find("stood up object 1: 1.9"), std::string::npos) << output;  // true 1.945 m
  EXPECT_EQ(outlining(40).at("polygon_px").size(), 2u);
  EXPECT_EQ(outlining(42).at("polygon_px").size(), 2u) << "Enter does not close two points";
  EXPECT_NE(output.find("stand up: a polygon needs three points or more"), std::string::npos) << output;
  EXPECT_TRUE(outlining(45).at("polygon_px").empty()) << "Esc drops it";
  EXPECT_TRUE(outlining(45).at("active").get<bool>()) << "and the tool stays on";
  EXPECT_EQ(rows.at(45).raw.at("cutouts").size(), 1u);
}

// O and the doorway's four corners clicked (TUNE seed 0's doorway in the left wall, from the
// scene's answers) open the wall there: a cutout of shape "opening", undoable; the saved
// copy's model opens it as wide and as high as the doorway is.
TEST_F(StandUp, ADoorwayClickedWithOOpensTheWall) {
  const nlohmann::json truth = nlohmann::json::parse(std::ifstream(dir_ / "seed_00000.json"));
  std::vector<glm::dvec2> corners;
  double widthM = 0, heightM = 0;
  for (const nlohmann::json& o : truth.at("openings")) {
    if (o.at("kind") != "opening" || o.at("wall") != "left_wall") continue;
    for (const nlohmann::json& p : o.at("corners_px")) corners.emplace_back(p[0].get<double>(), p[1].get<double>());
    widthM = std::abs(o["z_m"][0].get<double>() - o["z_m"][1].get<double>());
    heightM = o["y_m"][1].get<double>() - o["y_m"][0].get<double>();
  }
  ASSERT_EQ(corners.size(), 4u) << "no doorway in the left wall in the scene's answers";
  const auto first = edit("opening_layout", "2 quit\n");
  ASSERT_GE(first.size(), 2u);
  const Row& r = first.back();
  Script s;
  s.key(3, "O");
  for (int i = 0; i < 4; ++i) s.click(5 + 3 * i, r.toWindow(corners[i]));
  s.key(18, "ENTER");
  s.at(20, "save-copy opened.json");
  s.ctrlKey(22, "Z").at(25, "quit");
  std::string output;
  const auto rows = edit("opening", s.str(), &output);
  ASSERT_GE(rows.size(), 25u);
  const nlohmann::json cutouts = rows.at(20).raw.at("cutouts");
  ASSERT_EQ(cutouts.size(), 1u) << cutouts.dump() << output;
  EXPECT_EQ(cutouts[0].at("name"), "opening 1");
  EXPECT_EQ(cutouts[0].at("shape"), "opening");
  EXPECT_EQ(rows.at(24).raw.at("cutouts").size(), 0u) << "undone";
  EXPECT_NE(output.find("opening 1 opens the left wall: "), std::string::npos) << output;

  const std::string text = builtModel("opened");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(text, m, std::regex("opened: opening 1 \\([^)]*\\), an opening ([0-9.]+) m wide and ([0-9.]+) m high in the left wall")))
      << "no 'opened' line in the model";
  EXPECT_NEAR(std::stod(m[1]), widthM, 0.05) << "true " << widthM;  // measured 0.95 (true 0.947)
  EXPECT_NEAR(std::stod(m[2]), heightM, 0.02) << "true " << heightM;  // measured 2.03 (true 2.027)
}

// A cutout that cannot stand up where the corners put the corridor (in a file, or after a
// corner moved) is left painted: the list says so under its name, in the trace's
// "left_painted", and the others stand up as before.
TEST_F(StandUp, AnObjectThatCannotStandUpIsSaidLeftPaintedInTheList) {
  const std::optional<Person> her = person();
  ASSERT_TRUE(her.has_value()) << "no person in the scene's answers";
  nlohmann::json shot = nlohmann::json::parse(std::ifstream(dir_ / "seed_00000.json"));
  const double halfWidthPx = her->halfWidthPx;
  shot["cutouts"] = {{{"name", "her"},
                      {"outline_px", {{her->feet.x - halfWidthPx, her->head.y - 8}, {her->feet.x + halfWidthPx, her->head.y - 8},
                                      {her->feet.x + halfWidthPx, her->feet.y + 10}, {her->feet.x - halfWidthPx, her->feet.y + 10}}}},
                     {{"name", "sign"}, {"outline_px", {{480, 20}, {560, 20}, {560, 80}, {480, 80}}}}};
  std::ofstream(dir_ / "painted.json") << shot.dump();
  Script s;
  s.key(1, "P");  // the preview shown again: the list reads its full model
  s.at(3, "preview-wait").at(4, "capture left_painted.png").at(5, "quit");
  const auto rows = edit("left_painted", s.str(), nullptr, "painted.json");
  ASSERT_GE(rows.size(), 5u);
  const nlohmann::json cutouts = rows.at(4).raw.at("cutouts");
  ASSERT_EQ(cutouts.size(), 2u) << cutouts.dump();
  EXPECT_TRUE(cutouts[0].at("left_painted").is_null()) << cutouts.dump();
  ASSERT_TRUE(cutouts[1].at("left_painted").is_string()) << cutouts.dump();
  EXPECT_NE(cutouts[1]["left_painted"].get<std::string>().find("above the horizon"), std::string::npos) << cutouts.dump();
  EXPECT_TRUE(rows.at(1).raw.at("cutouts")[1].at("left_painted").is_null()) << "before the model is built";
}

// A rectangle around a lamp hanging above the horizon (TUNE seed 0's lamp 14, 4 px around
// its box as the photo shows it, rod included): it cannot stand on the floor, so U makes it
// a hanging cut-out at once ("it hangs from the ceiling"), and `build` of the saved copy
// hangs it from the ceiling.
TEST_F(StandUp, ALampAboveTheHorizonHangsFromTheCeiling) {
  const nlohmann::json truth = nlohmann::json::parse(std::ifstream(dir_ / "seed_00000.json"));
  const nlohmann::json* lamp = nullptr;
  for (const nlohmann::json& o : truth.at("objects")) {
    if (o.at("id") == 14) lamp = &o;
  }
  ASSERT_TRUE(lamp && lamp->at("kind") == "lamp") << "no lamp 14 in the scene's answers";
  auto shot = modeling::measureShotFile(dir_ / "seed_00000.json");
  ASSERT_TRUE(shot.ok()) << shot.message();
  const glm::dvec3 place(lamp->at("place_m")[0].get<double>(), lamp->at("place_m")[1].get<double>(),
                         lamp->at("place_m")[2].get<double>());
  const double drop = lamp->at("size_m")[1].get<double>(), half = 0.5 * lamp->at("size_m")[0].get<double>();
  glm::dvec2 lo(1e300), hi(-1e300);
  for (int k = 0; k < 8; ++k) {
    const glm::dvec3 corner(place.x + (k & 1 ? half : -half), k & 2 ? place.y + drop : place.y, place.z + (k & 4 ? half : -half));
    const glm::dvec2 px(metrology::projectWithMeasurement(shot->measurement, corner));
    lo = glm::min(lo, px), hi = glm::max(hi, px);
  }
  lo -= glm::dvec2(4.0), hi += glm::dvec2(4.0);

  const auto first = edit("layout", "2 quit\n");
  ASSERT_GE(first.size(), 2u);
  const Row& r = first.back();
  const glm::dvec2 a = r.toWindow(lo), b = r.toWindow(hi);
  Script s;
  s.key(3, "U");
  s.drag(5, a, b - a, 6);  // frames 5-12
  s.at(14, "save-copy hung.json").at(15, "capture hung.png").at(16, "quit");
  std::string output;
  const auto rows = edit("hang", s.str(), &output);
  ASSERT_GE(rows.size(), 15u);
  const nlohmann::json cutouts = rows.at(14).raw.at("cutouts");
  ASSERT_EQ(cutouts.size(), 1u) << output;
  EXPECT_EQ(cutouts[0].at("shape"), "hanging") << cutouts.dump();
  EXPECT_NE(output.find("stood up object 1: it hangs from the ceiling"), std::string::npos) << output;
  const std::string text = builtModel("hung");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(text, m, std::regex("stood up: object 1 \\([^)]*\\), a cut-out [0-9.]+ m wide and ([0-9.]+) m high hanging from the ceiling")))
      << "no hanging line in the model";
  EXPECT_NEAR(std::stod(m[1]), drop, 0.12 * drop);  // 0.81 m measured by StandingObjects.AHangingLampHangsWhereItHangs
}

}  // namespace
}  // namespace pw::edit::test
