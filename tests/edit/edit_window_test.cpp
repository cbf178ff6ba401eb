// photowalk edit, end to end under an X server (xvfb-run) on lavapipe: replay scripts
// drive the window; the trace (--trace), the captures and the saved files are checked.
// Validation is on (PW_VALIDATION=1): edit exits non-zero on any validation message.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "base/atomic_file.h"
#include "engine/scene/image.h"
#include "tests/edit/edit_run.h"
#include "tests/support/groundtruth.h"

namespace pw::edit::test {
namespace {
namespace fs = std::filesystem;
using pw::test::CommandRun;

constexpr int kWidth = 960, kHeight = 600;  // the canvas is the left 672 x 600

class Edit : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::path(PW_BINARY_DIR) / "test-output" / "edit";
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    const groundtruth::GroundTruth truth = groundtruth::loadGroundTruth("corridor_b");
    fs::copy_file(truth.image, dir_ / "corridor_b.png");
    fs::copy_file(truth.shot, dir_ / "corridor_b.json");  // a shot file (the answers are extra fields)
  }
  void SetUp() override {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no X display (run under xvfb-run)";
    setenv("PW_VALIDATION", "1", 1);
  }

  // Runs the editor on `file` (may be empty) with `script`; returns the trace.
  std::vector<Row> edit(const std::string& name, const std::string& file, const std::string& script,
                        const std::string& extra = "", std::string* output = nullptr) {
    const fs::path scriptPath = dir_ / (name + ".replay"), tracePath = dir_ / (name + ".jsonl");
    std::ofstream(scriptPath) << script;
    fs::remove(tracePath);
    const CommandRun run = photowalk("edit " + file + " --size " + std::to_string(kWidth) + "x" +
                                     std::to_string(kHeight) + " --no-vsync --replay " + scriptPath.string() +
                                     " --trace " + tracePath.string() + " " + extra);
    EXPECT_EQ(run.exitCode, 0) << run.output;
    if (output) *output = run.output;
    return readTrace(tracePath);
  }

  // A fresh copy of corridor_b.json (and its photo) named `name`.json.
  static std::string shotCopy(const std::string& name) {
    const fs::path path = dir_ / (name + ".json");
    fs::copy_file(dir_ / "corridor_b.json", path, fs::copy_options::overwrite_existing);
    return path.string();
  }

  static fs::path dir_;
};
fs::path Edit::dir_;

std::string bytesOf(const fs::path& path) {
  auto text = readFile(path);
  return text ? *text : std::string("<unreadable " + path.string() + ">");
}

const engine::Image& corridorPhoto() {
  static const engine::Image photo = [] {
    auto image = engine::loadImage(groundtruth::loadGroundTruth("corridor_b").image);
    return image ? *image : engine::Image{};
  }();
  return photo;
}

int channelDifference(const uint8_t* a, const uint8_t* b) {
  int most = 0;
  for (int c = 0; c < 3; ++c) most = std::max(most, std::abs(int(a[c]) - int(b[c])));
  return most;
}

TEST_F(Edit, APhotoWithoutCornersGetsThemFromDetection) {
  std::string output;
  // The capture (after the notes' five seconds) is the README's picture of it.
  const auto rows = edit("detect", (dir_ / "corridor_b.png").string(), "302 capture detected.png\n303 quit\n",
                         "", &output);
  ASSERT_GE(rows.size(), 303u);
  EXPECT_TRUE(fs::exists(dir_ / "detected.png"));
  const groundtruth::GroundTruth truth = groundtruth::loadGroundTruth("corridor_b");
  ASSERT_EQ(rows[0].corners.size(), 8u);
  for (int k = 0; k < 4; ++k) {
    // The far wall, measured: 0.39 px at most from the exact projections. P5..P8 go to
    // the photo's edge (detect's default), not to the scene's painted band (the answers').
    EXPECT_LT(glm::length(rows[0].corners[k] - truth.cornersPx[k]), 0.6) << "P" << k + 1;
  }
  for (int k = 4; k < 8; ++k) {
    EXPECT_TRUE(rows[0].corners[k].x >= 0 && rows[0].corners[k].y >= 0 && rows[0].corners[k].x <= truth.imageWidth - 1 &&
                rows[0].corners[k].y <= truth.imageHeight - 1)
        << "P" << k + 1;
  }
  EXPECT_EQ(rows[0].mode, "edit");
  ASSERT_TRUE(rows[0].size.has_value());  // it measures at once (camera height assumed 1.6 m: exact here)
  EXPECT_NEAR(rows[0].size->x, truth.widthM, 0.05);
  EXPECT_NEAR(rows[0].size->y, truth.heightM, 0.05);
  ASSERT_TRUE(rows[0].path.has_value());
  EXPECT_EQ(fs::path(*rows[0].path), dir_ / "corridor_b.shot.json");
  EXPECT_TRUE(rows[0].dirty);
  EXPECT_NE(output.find("corners detected (confidence"), std::string::npos) << output;
}

TEST_F(Edit, DraggingAHandleMovesItsCornerByTheDragOverTheScaleAtThreeZooms) {
  const std::string file = shotCopy("drag");
  const auto first = edit("drag_first", file, "1 quit\n");
  ASSERT_FALSE(first.empty());
  const glm::dvec2 handle = first[0].toWindow(first[0].corners[0]);  // P1

  // Fitted: drag 40 px right. Then 1:1 about the cursor (on the handle): 40 px down. Then
  // eight wheel steps in (5.96x): 40 px left and up. Then Shift (tenfold slower): 40 px right.
  Script s;
  s.drag(5, handle, {40, 0});
  const glm::dvec2 second = handle + glm::dvec2(40, 0);
  s.key(15, "1").drag(20, second, {0, 40});
  const glm::dvec2 third = second + glm::dvec2(0, 40);
  s.at(30, "wheel 8").drag(35, third, {-40, -40});
  const glm::dvec2 fourth = third + glm::dvec2(-40, -40);
  s.at(45, "key LEFT_SHIFT down").drag(46, fourth, {40, 0}).at(52, "key LEFT_SHIFT up").at(55, "quit");
  const auto rows = edit("drag", file, s.str());
  ASSERT_GE(rows.size(), 55u);

  struct Case {
    int before, after;  // rows around the drag
    glm::dvec2 byPx;    // window pixels
    double slow;
  };
  const Case cases[] = {{4, 10, {40, 0}, 1}, {19, 25, {0, 40}, 1}, {34, 40, {-40, -40}, 1}, {45, 51, {40, 0}, 0.1}};
  std::vector<double> scales;
  for (const Case& c : cases) {
    const double scale = rows[c.after].scale;
    EXPECT_EQ(rows[c.before].scale, scale);  // the drag does not zoom
    const glm::dvec2 moved = rows[c.after].corners[0] - rows[c.before].corners[0];
    const glm::dvec2 expected = c.byPx * c.slow / scale;
    // Measured: 1e-13 px (deltas in window pixels over the scale, summed).
    EXPECT_NEAR(moved.x, expected.x, 0.01) << "at " << scale << "x";
    EXPECT_NEAR(moved.y, expected.y, 0.01) << "at " << scale << "x";
    for (int k = 1; k < 8; ++k) EXPECT_EQ(rows[c.after].corners[k], rows[c.before].corners[k]);
    EXPECT_EQ(rows[c.after].selected.value_or(""), "P1");
    scales.push_back(scale);
  }
  EXPECT_NEAR(scales[0], first[0].scale, 1e-12);  // fitted
  EXPECT_EQ(scales[1], 1.0);
  EXPECT_NEAR(scales[2], std::pow(1.25, 8), 1e-9);
  EXPECT_TRUE(rows.back().dirty);
}

// A corner released a few pixels from its edge junction snaps onto it (the ring shows
// where, in the trace's snap_px); released far from any junction it stays where it was
// dropped; with Alt held it stays put.
TEST_F(Edit, ACornerReleasedByItsEdgeJunctionSnapsOntoItUnlessAltIsHeld) {
  const std::string file = shotCopy("snap");
  const auto first = edit("snap_first", file, "1 quit\n");
  ASSERT_FALSE(first.empty());
  const glm::dvec2 exact = first[0].corners[0];  // P1, the ground truth's
  const glm::dvec2 handle = first[0].toWindow(exact);
  Script s;
  s.drag(5, handle, {60, 0});                           // away from the junction: stays
  s.drag(15, handle + glm::dvec2(60, 0), {-55, 4});     // 5 px right, 4 down of it: snaps
  s.at(25, "key LEFT_ALT down").drag(26, handle, {5, 4}).at(33, "key LEFT_ALT up");  // Alt held: stays
  s.at(36, "quit");
  const auto rows = edit("snap", file, s.str());
  ASSERT_GE(rows.size(), 36u);
  const double scale = rows[4].scale;
  EXPECT_NEAR(rows[12].corners[0].x, exact.x + 60 / scale, 0.01);
  EXPECT_NEAR(rows[12].corners[0].y, exact.y, 0.01);
  EXPECT_LT(glm::length(rows[22].corners[0] - exact), 1.0) << rows[22].corners[0].x << "," << rows[22].corners[0].y;
  const glm::dvec2 held = rows[34].corners[0] - rows[22].corners[0];
  EXPECT_NEAR(held.x, 5 / scale, 0.01);
  EXPECT_NEAR(held.y, 4 / scale, 0.01);
}

TEST_F(Edit, TheWheelKeepsThePointUnderTheCursorInPlace) {
  const std::string file = shotCopy("wheel");
  struct Zoom {
    glm::dvec2 at;
    int steps;
  };
  // Over the photo, near its edges, beyond them, out to the least and in to the most.
  const Zoom zooms[] = {{{100, 100}, 3}, {{500, 400}, 5}, {{20, 580}, -2}, {{650, 30}, 10}, {{300, 300}, -30},
                        {{300, 300}, 60}, {{410, 330}, -10}};
  Script s;
  int frame = 5;
  for (const Zoom& z : zooms) {
    s.move(frame, z.at).at(frame + 1, "wheel " + std::to_string(z.steps));
    frame += 5;
  }
  s.at(frame, "quit");
  const auto rows = edit("wheel", file, s.str());
  ASSERT_GE(rows.size(), size_t(frame));
  frame = 5;
  double most = 0, least = 1e9, worst = 0;
  for (const Zoom& z : zooms) {
    const Row& before = rows[frame];
    const Row& after = rows[frame + 1];
    const glm::dvec2 under = (z.at - before.offset) / before.scale;
    const double error = glm::length(after.toWindow(under) - z.at);
    EXPECT_LT(error, 0.5) << "wheel " << z.steps << " at " << z.at.x << "," << z.at.y;  // measured: 1e-13
    worst = std::max(worst, error);
    EXPECT_NE(after.scale, before.scale);
    most = std::max(most, after.scale);
    least = std::min(least, after.scale);
    frame += 5;
  }
  EXPECT_EQ(most, 64.0);  // at least 32 screen pixels per photo pixel is promised
  EXPECT_NEAR(least, 0.25 * rows[0].scale, 1e-12);
  std::printf("wheel: worst anchor error %.3g window px over %zu zooms\n", worst, std::size(zooms));
}

TEST_F(Edit, ThePhotoIsDrawnWhereTheTraceSaysAtEveryZoom) {
  // With the guides hidden (H), the canvas shows the photo alone: at 8x and 64x (nearest)
  // every window pixel is the photo pixel offset + scale * (u, v) puts there.
  const std::string file = shotCopy("placement");
  Script s;
  s.key(2, "H").move(3, {333, 301}).at(4, "wheel 11").at(6, "capture placement_8x.png");  // 0.64 * 1.25^11 = 7.5
  s.move(8, {200, 450}).at(9, "wheel 100").at(11, "capture placement_64x.png").at(12, "quit");
  const auto rows = edit("placement", file, s.str());
  ASSERT_GE(rows.size(), 12u);
  const engine::Image& photo = corridorPhoto();
  ASSERT_FALSE(photo.empty());
  for (const auto& [name, row] : {std::pair{"placement_8x.png", rows[6]}, std::pair{"placement_64x.png", rows[11]}}) {
    auto shot = engine::loadImage(dir_ / name);
    ASSERT_TRUE(shot.ok()) << shot.message();
    ASSERT_GE(row.scale, 4.0);  // nearest-neighbour from 4x
    int checked = 0, wrong = 0;
    for (int y = 40; y < kHeight - 100; y += 7) {  // below the status line, above the messages
      for (int x = 0; x < 672; x += 7) {
        const glm::dvec2 p = (glm::dvec2(x + 0.5, y + 0.5) - row.offset) / row.scale;
        const glm::dvec2 nearest = glm::round(p);
        // Half a window pixel from a photo pixel's edge could go either way.
        if (glm::any(glm::greaterThan(glm::abs(p - nearest) * row.scale, glm::dvec2(0.5 * row.scale - 0.5)))) continue;
        if (nearest.x < 0 || nearest.y < 0 || nearest.x >= photo.width || nearest.y >= photo.height) continue;
        ++checked;
        wrong += channelDifference(shot->pixel(x, y), photo.pixel(int(nearest.x), int(nearest.y))) > 2;
      }
    }
    EXPECT_GT(checked, 1000) << name;
    EXPECT_EQ(wrong, 0) << name << ": " << wrong << " of " << checked << " pixels are not the photo's";
  }
}

TEST_F(Edit, UndoEverythingThenRedoEverythingSavesTheSameBytes) {
  const std::string file = shotCopy("undo");
  const auto first = edit("undo_first", file, "1 quit\n");
  ASSERT_FALSE(first.empty());
  const glm::dvec2 p1 = first[0].toWindow(first[0].corners[0]), p5 = first[0].toWindow(first[0].corners[4]);
  Script s;
  s.at(2, "save-copy undo_a0.json");
  s.drag(5, p1, {13, 7});                               // step 1
  s.drag(15, p5, {-21, 9}, 6);                          // step 2
  s.key(25, "TAB").key(26, "RIGHT").key(27, "DOWN");    // Tab from P5 selects P6; two nudges: steps 3, 4
  s.at(30, "save-copy undo_b0.json");
  for (int i = 0; i < 4; ++i) s.ctrlKey(32 + i, "Z");
  s.at(37, "save-copy undo_a1.json");
  s.ctrlKey(40, "Z", true).ctrlKey(41, "Y").ctrlKey(42, "Z", true).ctrlKey(43, "Y");
  s.at(45, "save-copy undo_b1.json").ctrlKey(46, "S").at(48, "quit");
  const auto rows = edit("undo", file, s.str());
  ASSERT_GE(rows.size(), 48u);

  EXPECT_EQ(bytesOf(dir_ / "undo_a1.json"), bytesOf(dir_ / "undo_a0.json"));
  EXPECT_EQ(bytesOf(dir_ / "undo_b1.json"), bytesOf(dir_ / "undo_b0.json"));
  EXPECT_NE(bytesOf(dir_ / "undo_b0.json"), bytesOf(dir_ / "undo_a0.json"));
  EXPECT_EQ(bytesOf(file), bytesOf(dir_ / "undo_b0.json"));  // Ctrl+S wrote the redone state

  // One drag is one step, one nudge too: the first undo takes back the last nudge, the
  // third the second drag, the fourth the first drag.
  EXPECT_EQ(rows[32].corners[5], rows[26].corners[5]);  // after one undo: P6 as after the first nudge
  EXPECT_EQ(rows[34].corners, rows[14].corners);        // three undone: as after the first drag
  EXPECT_EQ(rows[35].corners, rows[4].corners);         // four: as opened
  EXPECT_NE(rows[14].corners[0], rows[4].corners[0]);
  EXPECT_EQ(rows[26].selected.value_or(""), "P6");
  // Dirty follows the file: clean as opened, dirty when edited, clean when all is
  // undone (the shot is the file's again), dirty when redone, clean after Ctrl+S.
  EXPECT_FALSE(rows[4].dirty);
  EXPECT_TRUE(rows[30].dirty);
  EXPECT_FALSE(rows[36].dirty);
  EXPECT_TRUE(rows[44].dirty);
  EXPECT_FALSE(rows[47].dirty);
}

TEST_F(Edit, SaveThenReopenGivesTheSameCornersAndTheMeasurementOfTheMeasureCommand) {
  const fs::path saved = dir_ / "saved.json";
  fs::remove(saved);
  const auto first = edit("save_first", (dir_ / "corridor_b.png").string(), "1 quit\n", "-o " + saved.string());
  ASSERT_FALSE(first.empty());
  EXPECT_FALSE(fs::exists(saved));
  const glm::dvec2 p6 = first[0].toWindow(first[0].corners[5]);
  Script s;
  s.drag(5, p6, {9.5, -4.25}).ctrlKey(15, "S").at(18, "quit");
  const auto rows = edit("save", (dir_ / "corridor_b.png").string(), s.str(), "-o " + saved.string());
  ASSERT_GE(rows.size(), 18u);
  ASSERT_TRUE(fs::exists(saved));
  EXPECT_TRUE(rows[14].dirty);
  EXPECT_FALSE(rows[15].dirty);
  EXPECT_EQ(fs::path(rows[15].path.value_or("")), saved);

  const auto reopened = edit("save_reopen", saved.string(), "1 quit\n");
  ASSERT_FALSE(reopened.empty());
  EXPECT_EQ(reopened[0].corners, rows.back().corners);  // every bit
  EXPECT_FALSE(reopened[0].dirty);

  const CommandRun measured = photowalk("measure " + saved.string());
  ASSERT_EQ(measured.exitCode, 0) << measured.output;
  const nlohmann::json m = nlohmann::json::parse(measured.output.substr(measured.output.find('{')));
  ASSERT_TRUE(rows.back().size.has_value());
  EXPECT_EQ(rows.back().size->x, m.at("width_m").get<double>());
  EXPECT_EQ(rows.back().size->y, m.at("height_m").get<double>());
  EXPECT_EQ(rows.back().size->z, m.at("length_m").get<double>());
}

TEST_F(Edit, ACaptureDuringADragShowsThePhotoTheOverlayAndTheLoupe) {
  const std::string file = shotCopy("loupe");
  const auto first = edit("loupe_first", file, "1 quit\n");
  ASSERT_FALSE(first.empty());
  const glm::dvec2 p5 = first[0].toWindow(first[0].corners[4]);
  Script s;
  s.move(5, p5).at(5, "mouse left down").move(6, p5 + glm::dvec2(6, -3)).move(7, p5 + glm::dvec2(12, -6));
  s.at(8, "capture loupe.png").at(9, "mouse left up").at(10, "quit");
  const auto rows = edit("loupe", file, s.str());
  ASSERT_GE(rows.size(), 10u);
  const Row& row = rows[8];
  auto captured = engine::loadImage(dir_ / "loupe.png");
  ASSERT_TRUE(captured.ok()) << captured.message();
  ASSERT_EQ(captured->width, kWidth);
  const engine::Image& photo = corridorPhoto();

  // The photo: the floor below the near cross-section (no guide over it), as a block's
  // mean against the photo's mean over the same place (trilinear at 0.64x).
  {
    const glm::dvec2 a = row.toWindow({440, 690}), b = row.toWindow({600, 740});
    double shown = 0, expected = 0;
    int n = 0;
    for (int y = int(a.y); y < int(b.y); ++y) {
      for (int x = int(a.x); x < int(b.x); ++x, ++n) shown += captured->pixel(x, y)[1];
    }
    int m = 0;
    for (int v = 690; v < 740; ++v) {
      for (int u = 440; u < 600; ++u, ++m) expected += photo.pixel(u, v)[1];
    }
    ASSERT_GT(n, 500);
    EXPECT_NEAR(shown / n, expected / m, 3.0);  // measured: 0.3 of 255
  }
  // Beyond the photo's edge: the canvas's own grey (0.17, 0.17, 0.19).
  {
    const glm::dvec2 beyond = row.toWindow({1000, -40});  // above the photo, right of the status line
    const uint8_t grey[3] = {43, 43, 48};
    EXPECT_LE(channelDifference(captured->pixel(int(beyond.x), int(beyond.y)), grey), 1);
  }
  // The overlay: P6's handle (not dragged) in the near floor's green (70, 220, 90; the
  // shell's sRGB swapchain shows ImGui's colours as 143, 239, 160 today), on a wall of greys.
  {
    const glm::dvec2 p6 = row.toWindow(row.corners[5]);
    const uint8_t* handle = captured->pixel(int(p6.x), int(p6.y));
    EXPECT_GT(handle[1], 200);
    EXPECT_GT(handle[1], handle[0] + 60);
    EXPECT_GT(handle[1], handle[2] + 50);
    const glm::dvec2 wall = row.toWindow(row.corners[5] + glm::dvec2(40, -40));  // no guide there
    const uint8_t* grey = captured->pixel(int(wall.x), int(wall.y));
    EXPECT_LT(std::abs(int(grey[1]) - int(grey[0])), 20);
  }
  // The loupe: where the trace puts it, P5 at its centre, each photo pixel a square of
  // scale x scale window pixels (nearest), away from the lines drawn through it.
  const nlohmann::json& loupe = row.raw.at("loupe");
  ASSERT_TRUE(loupe.is_object());
  EXPECT_EQ(loupe.at("corner"), "P5");
  const double scale = loupe.at("scale");
  EXPECT_GE(scale, 8.0);
  const glm::dvec2 offset(loupe["offset"][0], loupe["offset"][1]);
  const glm::dvec2 rectMin(loupe["rect"][0], loupe["rect"][1]), rectSize(loupe["rect"][2], loupe["rect"][3]);
  const glm::dvec2 centre = rectMin + 0.5 * rectSize;
  EXPECT_LT(glm::length(offset + scale * row.corners[4] - centre), 1e-6);
  int checked = 0, wrong = 0;
  for (int du = -8; du <= 8; ++du) {
    for (int dv = -8; dv <= 8; ++dv) {
      const glm::dvec2 photoPx = glm::round(row.corners[4]) + glm::dvec2(du, dv);
      const glm::dvec2 at = offset + scale * photoPx;  // the square's centre
      if (glm::any(glm::lessThan(at, rectMin + 3.0)) || glm::any(glm::greaterThan(at, rectMin + rectSize - 3.0))) continue;
      // Away from the loupe's label, the crosshair and the three edges through P5.
      if (at.x < rectMin.x + 70 && at.y < rectMin.y + 24) continue;
      bool nearLine = std::abs(at.x - centre.x) < 4 || std::abs(at.y - centre.y) < 4;
      for (int n : {5, 6, 2}) {  // P6, P7, P3
        const glm::dvec2 d = glm::normalize(row.corners[n] - row.corners[4]);
        const glm::dvec2 r = at - centre;
        nearLine |= std::abs(r.x * d.y - r.y * d.x) < 4;
      }
      if (nearLine) continue;
      ++checked;
      wrong += channelDifference(captured->pixel(int(at.x), int(at.y)), photo.pixel(int(photoPx.x), int(photoPx.y))) > 2;
    }
  }
  EXPECT_GT(checked, 40);
  EXPECT_EQ(wrong, 0) << wrong << " of " << checked << " loupe squares are not the photo's pixel";
  // Its border is white.
  const uint8_t* border = captured->pixel(int(rectMin.x) - 1, int(centre.y) + 20);
  EXPECT_GE(std::min({border[0], border[1], border[2]}), 230);
  std::printf("loupe: %s, %.0fx, %d squares checked\n", (dir_ / "loupe.png").c_str(), scale, checked);
}

TEST_F(Edit, WKeyWalksTheModelAndEscComesBackToTheEditorAsItWas) {
  const std::string file = shotCopy("walk");
  Script s;
  s.at(3, "key LEFT_ALT down").key(3, "3").at(3, "key LEFT_ALT up");
  s.move(4, {250, 200}).at(5, "wheel 2").key(10, "W").at(30, "capture walk.png").key(40, "ESCAPE").at(45, "quit");
  const auto rows = edit("walk", file, s.str());
  ASSERT_GE(rows.size(), 45u);
  EXPECT_EQ(rows[9].mode, "edit");
  for (int f = 10; f < 40; ++f) {
    EXPECT_EQ(rows[f].mode, "walk") << "frame " << f;
    EXPECT_TRUE(rows[f].raw.contains("x"));
    EXPECT_TRUE(rows[f].raw.contains("document"));
  }
  for (int f = 40; f < 45; ++f) EXPECT_EQ(rows[f].mode, "edit") << "frame " << f;
  // The walk starts at the photo's camera: 0.4 m right of the centre line, 1.6 m up,
  // 5.5 m before the near corners (the scene's answers).
  EXPECT_NEAR(rows[12].raw.at("x").get<double>(), 0.4, 0.05);
  EXPECT_NEAR(rows[12].raw.at("y").get<double>(), 1.6, 0.05);
  EXPECT_NEAR(rows[12].raw.at("z").get<double>(), 5.5, 0.05);
  // Back in the editor exactly as it was: the view, the corners, the selection.
  EXPECT_EQ(rows[40].scale, rows[9].scale);
  EXPECT_EQ(rows[40].offset, rows[9].offset);
  EXPECT_EQ(rows[40].corners, rows[9].corners);
  EXPECT_EQ(rows[40].selected.value_or(""), "P3");
  EXPECT_EQ(rows[9].selected.value_or(""), "P3");
  EXPECT_NE(rows[9].scale, rows[0].scale);  // the zoom was changed before the walk
  // The walk's frame is the model, not a blank: its pixels vary.
  auto frame = engine::loadImage(dir_ / "walk.png");
  ASSERT_TRUE(frame.ok()) << frame.message();
  double sum = 0, sumSq = 0;
  const size_t n = frame->rgba.size() / 4;
  for (size_t i = 0; i < n; ++i) {
    sum += frame->rgba[4 * i + 1];
    sumSq += double(frame->rgba[4 * i + 1]) * frame->rgba[4 * i + 1];
  }
  EXPECT_GT(std::sqrt(sumSq / n - (sum / n) * (sum / n)), 10.0);
}

TEST_F(Edit, KeysSelectNudgeFitAndShowOneToOne) {
  const std::string file = shotCopy("keys");
  Script s;
  s.key(2, "TAB").key(3, "TAB").at(4, "key LEFT_SHIFT down").key(4, "TAB").key(5, "TAB").at(5, "key LEFT_SHIFT up");
  s.at(6, "key LEFT_ALT down").key(6, "5").at(6, "key LEFT_ALT up");
  s.key(8, "RIGHT").at(9, "key LEFT_SHIFT down").key(9, "DOWN").at(9, "key LEFT_SHIFT up");
  s.move(10, {300, 250}).key(11, "1").key(13, "F");
  s.ctrlKey(15, "Z");  // takes back the 0.1 px nudge only
  s.at(20, "quit");
  const auto rows = edit("keys", file, s.str());
  ASSERT_GE(rows.size(), 20u);
  EXPECT_FALSE(rows[1].selected.has_value());
  EXPECT_EQ(rows[2].selected.value_or(""), "P1");
  EXPECT_EQ(rows[3].selected.value_or(""), "P2");
  EXPECT_EQ(rows[5].selected.value_or(""), "P8");  // Shift+Tab twice: P1, then round to P8
  EXPECT_EQ(rows[6].selected.value_or(""), "P5");  // Alt+5
  EXPECT_NEAR(rows[8].corners[4].x - rows[7].corners[4].x, 1.0, 1e-12);
  EXPECT_NEAR(rows[9].corners[4].y - rows[8].corners[4].y, 0.1, 1e-12);
  EXPECT_EQ(rows[9].corners[4].x, rows[8].corners[4].x);
  EXPECT_EQ(rows[11].scale, 1.0);
  // 1:1 about the cursor: the photo point under it stays.
  const glm::dvec2 under = (glm::dvec2(300, 250) - rows[10].offset) / rows[10].scale;
  EXPECT_LT(glm::length(rows[11].toWindow(under) - glm::dvec2(300, 250)), 1e-9);
  EXPECT_EQ(rows[13].scale, rows[0].scale);  // F: fitted again
  EXPECT_EQ(rows[13].offset, rows[0].offset);
  EXPECT_EQ(rows[15].corners[4], rows[8].corners[4]);
  for (int f = 0; f < 20; ++f) EXPECT_EQ(rows[f].mode, "edit");
}

TEST_F(Edit, PanWithTheMiddleOrRightButtonOrSpaceAndLeftButEscCancelsADrag) {
  const std::string file = shotCopy("pan");
  const auto first = edit("pan_first", file, "1 quit\n");
  ASSERT_FALSE(first.empty());
  const glm::dvec2 p2 = first[0].toWindow(first[0].corners[1]);
  Script s;
  s.drag(2, {100, 100}, {30, 20}, 2, "middle");                         // rows 1 -> 5
  s.drag(6, {400, 100}, {-10, 50}, 2, "right");                         // 5 -> 9
  s.at(10, "key SPACE down").drag(10, {300, 300}, {25, -5}, 2).at(14, "key SPACE up");  // 9 -> 13
  s.drag(15, {620, 560}, {-50, -50}, 2);                                // left on no handle: nothing
  const glm::dvec2 p2Now = p2 + glm::dvec2(30 - 10 + 25, 20 + 50 - 5);
  s.move(20, p2Now).at(21, "mouse left down").move(22, p2Now + glm::dvec2(30, 30)).key(23, "ESCAPE");
  s.at(24, "mouse left up").at(26, "quit");
  const auto rows = edit("pan", file, s.str());
  ASSERT_GE(rows.size(), 26u);
  EXPECT_EQ(rows[5].offset - rows[1].offset, glm::dvec2(30, 20));
  EXPECT_EQ(rows[9].offset - rows[5].offset, glm::dvec2(-10, 50));
  EXPECT_EQ(rows[13].offset - rows[9].offset, glm::dvec2(25, -5));
  EXPECT_EQ(rows[19].offset, rows[13].offset);
  EXPECT_EQ(rows[19].corners, rows[0].corners);
  for (const Row& r : rows) EXPECT_EQ(r.scale, rows[0].scale);
  EXPECT_NE(rows[22].corners[1], rows[0].corners[1]);  // P2 taken and dragged...
  EXPECT_EQ(rows[23].corners[1], rows[0].corners[1]);  // ... and Esc put it back
  EXPECT_FALSE(rows[25].dirty);                        // nothing was changed in the end
}

TEST_F(Edit, NoFileABadFileAndAPhotoWithoutACorridorKeepTheEditorOpen) {
  // No file: empty, then a dropped shot file opens.
  const auto empty = edit("empty", "", std::string("2 capture empty.png\n5 drop ") + shotCopy("dropped") + "\n8 quit\n");
  ASSERT_GE(empty.size(), 8u);
  EXPECT_TRUE(empty[0].corners.empty());
  EXPECT_FALSE(empty[0].path.has_value());
  EXPECT_FALSE(empty[0].size.has_value());
  ASSERT_EQ(empty[5].corners.size(), 8u);
  EXPECT_EQ(fs::path(empty[5].path.value_or("")), dir_ / "dropped.json");

  // A shot file with an error: a message, and the editor stays open with nothing in it.
  const fs::path bad = dir_ / "bad.json";
  std::ofstream(bad) << "{\"image\": \"corridor_b.png\", \"focal_px\": 800, \"camera_height_m\": 1.6}";
  std::string output;
  const auto badRows = edit("bad", bad.string(), "3 quit\n", "", &output);
  ASSERT_GE(badRows.size(), 3u);
  EXPECT_TRUE(badRows[2].corners.empty());
  EXPECT_NE(output.find("error: " + bad.string() + ": missing field \"corners_px\""), std::string::npos) << output;

  // A photo where no corridor is found: the default box, and a line saying so.
  const fs::path grey = dir_ / "grey.png";
  ASSERT_TRUE(cv::imwrite(grey.string(), cv::Mat(480, 640, CV_8UC3, cv::Scalar(90, 100, 110))));
  const auto greyRows = edit("grey", grey.string(), "3 quit\n", "", &output);
  ASSERT_GE(greyRows.size(), 3u);
  ASSERT_EQ(greyRows[0].corners.size(), 8u);
  EXPECT_EQ(greyRows[0].corners[0], glm::dvec2(0.4 * 640, 0.4 * 480));
  EXPECT_EQ(greyRows[0].corners[5], glm::dvec2(0.9 * 640, 0.9 * 480));
  EXPECT_NE(output.find("no corridor found"), std::string::npos) << output;
  // A placeholder until a corner is moved: no dimensions (the default box measures, but
  // not the corridor), and W says why instead of walking it. Once a corner is moved,
  // it measures, and the placeholder's note has gone.
  EXPECT_FALSE(greyRows.back().size.has_value());
  EXPECT_NE(output.find("a default box from the image size, not the corridor's"), std::string::npos) << output;
  Script s;
  s.key(3, "W", 1).drag(6, greyRows.back().toWindow(greyRows.back().corners[0]), {12, 8}).at(14, "quit");
  std::string movedOutput;
  const auto movedRows = edit("grey_moved", grey.string(), s.str(), "", &movedOutput);
  ASSERT_GE(movedRows.size(), 14u);
  EXPECT_NE(movedOutput.find("walk: the corners cannot be measured yet: the box is a placeholder"), std::string::npos)
      << movedOutput;
  EXPECT_EQ(movedRows[5].mode, "edit");  // W did not walk
  EXPECT_FALSE(movedRows[5].size.has_value());
  EXPECT_NE(movedRows.back().corners[0], greyRows.back().corners[0]);
  EXPECT_TRUE(movedRows.back().size.has_value());
}

}  // namespace
}  // namespace pw::edit::test
