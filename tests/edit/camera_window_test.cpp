// photowalk edit's camera, end to end under an X server (xvfb-run) on lavapipe: a JPEG
// stored on its side with EXIF (focal length, sensor, Orientation 6) opens upright with
// the EXIF focal length in the trace; the principal point's handle is dragged and the
// drag undone; a reference length is picked on the canvas, typed in the panel and made
// the scale; a crossed corner is ringed on its handle. Validation on (PW_VALIDATION=1).
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "base/atomic_file.h"
#include "tests/edit/edit_run.h"
#include "tests/support/exif_jpeg.h"
#include "tests/support/groundtruth.h"

namespace pw::edit::test {
namespace {
namespace fs = std::filesystem;
using pw::test::CommandRun;

// Tall and wide enough that the whole Camera panel (378 px wide) shows without scrolling.
constexpr int kWidth = 1260, kHeight = 1000;
constexpr double kFocalMm = 5.02299, kPxPerMm = 160.0;  // corridor_b's 803.68 px on a 6.4 x 4.8 mm sensor

class EditCamera : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::path(PW_BINARY_DIR) / "test-output" / "edit_camera";
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    // corridor_b stored on its side (turned anticlockwise), Orientation 6 to turn it back.
    const groundtruth::GroundTruth truth = groundtruth::loadGroundTruth("corridor_b");
    cv::Mat stored;
    cv::rotate(cv::imread(truth.image.string()), stored, cv::ROTATE_90_COUNTERCLOCKWISE);
    pw::test::ExifFields f;
    f.make = "Photowalk";
    f.model = "Corridor Cam";
    f.orientation = 6;
    f.focalLength = {unsigned(kFocalMm * 100000 + 0.5), 100000};
    f.focalPlaneXResolution = f.focalPlaneYResolution = std::pair<unsigned, unsigned>{1600, 1};  // px per cm
    f.focalPlaneResolutionUnit = 3;
    pw::test::writeBytes(dir_ / "turned.jpg", pw::test::jpegWithApp1(stored, pw::test::exifBlock(f)));
  }
  void SetUp() override {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no X display (run under xvfb-run)";
    setenv("PW_VALIDATION", "1", 1);
  }

  // Runs the editor on the EXIF photo with `script`, the 3D preview hidden (P) so that the
  // whole Camera panel fits in the window (`hidePreview`), at `width` x `height`.
  std::vector<Row> edit(const std::string& name, const std::string& script, bool hidePreview = true, int width = kWidth,
                        int height = kHeight) {
    const fs::path scriptPath = dir_ / (name + ".replay"), tracePath = dir_ / (name + ".jsonl");
    std::ofstream(scriptPath) << (hidePreview ? "0 key P down\n0 key P up\n" : "") << script;
    fs::remove(tracePath);
    const CommandRun run = photowalk("edit " + (dir_ / "turned.jpg").string() + " --size " + std::to_string(width) +
                                     "x" + std::to_string(height) + " --no-vsync --replay " + scriptPath.string() +
                                     " --trace " + tracePath.string());
    EXPECT_EQ(run.exitCode, 0) << run.output;
    return readTrace(tracePath);
  }

  static fs::path dir_;
};
fs::path EditCamera::dir_;

glm::dvec2 principal(const Row& row) {
  const auto& p = row.raw.at("camera").at("principal_px");
  return {p[0].get<double>(), p[1].get<double>()};
}

// The centre of a Camera panel widget, from the trace.
glm::dvec2 widget(const Row& row, const std::string& name) {
  const auto& widgets = row.raw.at("camera").at("widgets");
  if (!widgets.contains(name)) {
    ADD_FAILURE() << "no widget '" << name << "' in " << widgets.dump();
    return {-1, -1};
  }
  const auto& r = widgets[name];
  EXPECT_LT(r[1].get<double>() + r[3].get<double>(), kHeight) << "widget '" << name << "' is below the window";
  return {r[0].get<double>() + 0.5 * r[2].get<double>(), r[1].get<double>() + 0.5 * r[3].get<double>()};
}

TEST_F(EditCamera, AnExifPhotoOnItsSideOpensUprightWithItsFocalLength) {
  const auto rows = edit("open", "5 quit\n");
  ASSERT_GE(rows.size(), 5u);
  const auto& camera = rows[0].raw.at("camera");
  EXPECT_NEAR(camera.at("focal_px").get<double>(), kFocalMm * kPxPerMm, 1e-6);
  EXPECT_NEAR(camera.at("sensor_width_mm").get<double>(), 6.4, 1e-9);  // the stored image's y axis, across the photo
  EXPECT_EQ(camera.at("focal_source").get<std::string>().rfind("EXIF FocalLength 5.02 mm with FocalPlaneXResolution", 0), 0u)
      << camera.dump();
  EXPECT_EQ(camera.at("exif").at("orientation"), 6);
  EXPECT_EQ(camera.at("exif").at("model"), "Corridor Cam");
  EXPECT_TRUE(camera.at("principal_default").get<bool>());
  EXPECT_NEAR(principal(rows[0]).x, 511.5, 1e-9);  // the centre of the upright 1024 x 768 photo
  EXPECT_NEAR(principal(rows[0]).y, 383.5, 1e-9);
  // Upright: detection with the EXIF focal length finds the scene's corners.
  const groundtruth::GroundTruth truth = groundtruth::loadGroundTruth("corridor_b");
  ASSERT_EQ(rows[0].corners.size(), 8u);
  // The far wall; P5..P8 go to the photo's edge (detect's default), not the painted band.
  for (int k = 0; k < 4; ++k) EXPECT_LT(glm::length(rows[0].corners[k] - truth.cornersPx[k]), 1.0) << "P" << k + 1;
  for (int k = 4; k < 8; ++k) {
    EXPECT_TRUE(rows[0].corners[k].x >= 0 && rows[0].corners[k].y >= 0 && rows[0].corners[k].x <= 1023 &&
                rows[0].corners[k].y <= 767)
        << "P" << k + 1;
  }
  ASSERT_TRUE(rows[0].size);
  EXPECT_NEAR(rows[0].size->x, truth.widthM, 0.05);
  EXPECT_TRUE(rows[0].raw.at("handle_warnings").empty()) << rows[0].raw.at("handle_warnings").dump();
}

// Issue 23: at 1280x720 with the 3D preview open, a new photo's notes (EXIF focal
// length, corners detected, camera height assumed) and its measurement took the panel
// down to the Camera header: the camera height, which the notes ask for, needed a scroll.
TEST_F(EditCamera, TheFocalLengthAndCameraHeightAreAboveThePreviewAt1280x720) {
  const auto rows = edit("fold", "3 quit\n", /*hidePreview=*/false, 1280, 720);
  ASSERT_GE(rows.size(), 3u);
  const auto& preview = rows.back().raw.at("preview");
  ASSERT_TRUE(preview.at("shown").get<bool>()) << preview.dump();
  const double panelBottom = preview.at("rect")[1].get<double>() - 30;  // the preview's toolbar above its pane
  const auto& widgets = rows.back().raw.at("camera").at("widgets");
  for (const char* name : {"focal mm", "camera height", "camera height m"}) {
    ASSERT_TRUE(widgets.contains(name)) << name << " in " << widgets.dump();
    const auto& r = widgets[name];
    EXPECT_LE(r[1].get<double>() + r[3].get<double>(), panelBottom) << "'" << name << "' below the fold: " << r.dump();
  }
}

TEST_F(EditCamera, ThePrincipalPointHandleDragsAndUndoesAndAReferenceLengthSetsTheScale) {
  const auto first = edit("layout", "3 quit\n");
  ASSERT_GE(first.size(), 3u);
  const Row& r0 = first.back();
  const glm::dvec2 pp = r0.toWindow(principal(r0));

  // The principal point dragged 40 px right and 30 up, undone; the reference ticked.
  Script s;
  s.drag(5, pp, {40, -30});
  s.ctrlKeyHeld(14, "Z");
  s.click(22, widget(r0, "reference length"));
  const int prefixEnd = 30;
  const auto second = edit("reference_on", s.str() + std::to_string(prefixEnd) + " quit\n");
  ASSERT_GE(second.size(), size_t(prefixEnd));
  const glm::dvec2 moved = principal(second[11]) - principal(second[4]);
  EXPECT_NEAR(moved.x, 40 / r0.scale, 0.01);
  EXPECT_NEAR(moved.y, -30 / r0.scale, 0.01);
  EXPECT_FALSE(second[11].raw["camera"]["principal_default"].get<bool>());
  ASSERT_TRUE(second[11].size && second[4].size && second[20].size);
  EXPECT_NE(second[11].size->z, second[4].size->z);  // the length follows the principal point
  EXPECT_TRUE(second[20].raw["camera"]["principal_default"].get<bool>());  // one undo step
  EXPECT_EQ(principal(second[20]), principal(second[4]));
  const auto& reference = second[prefixEnd - 1].raw["camera"]["reference"];
  ASSERT_TRUE(reference.is_object()) << second[prefixEnd - 1].raw["camera"].dump();
  EXPECT_EQ(reference["from"], "P3");
  EXPECT_EQ(reference["to"], "P4");
  EXPECT_NEAR(reference["length_m"].get<double>(), second[20].size->x, 1e-9);  // as it measures: the width

  // Then: pick P1 and P2 on the canvas and make the reference the scale (the camera
  // height off); the reference's length field then has moved up a row, so it is found
  // from this run's trace.
  const Row& r1 = second[prefixEnd - 1];
  s.click(32, widget(r1, "pick"));
  s.click(38, r1.toWindow(r1.corners[0]));
  s.click(44, r1.toWindow(r1.corners[1]));
  s.click(50, widget(r1, "camera height"));
  const int thirdEnd = 58;
  const auto third = edit("reference_scale", s.str() + std::to_string(thirdEnd) + " quit\n");
  ASSERT_GE(third.size(), size_t(thirdEnd));
  const auto& picked = third[47].raw["camera"]["reference"];
  EXPECT_EQ(picked["from"], "P1");
  EXPECT_EQ(picked["to"], "P2");
  EXPECT_NEAR(picked["length_m"].get<double>(), reference["length_m"].get<double>(), 1e-12);  // kept
  EXPECT_NEAR(third[47].raw["camera"]["camera_height_m"].get<double>(), 1.6, 1e-12);
  const Row& r2 = third[thirdEnd - 1];
  EXPECT_TRUE(r2.raw["camera"]["camera_height_m"].is_null()) << r2.raw["camera"].dump();

  // Type 4.5 m into the reference's field; undo, redo; save.
  s.click(60, widget(r2, "reference m"));
  s.ctrlKeyHeld(64, "A").at(70, "type 4.5").key(72, "ENTER", 2);
  s.at(80, "capture camera.png");
  s.ctrlKeyHeld(82, "Z");
  s.ctrlKeyHeld(90, "Y");
  s.ctrlKeyHeld(98, "S");
  s.at(106, "quit");
  const auto rows = edit("reference", s.str());
  ASSERT_GE(rows.size(), 106u);
  ASSERT_TRUE(rows[57].size && rows[78].size && rows[88].size && rows[96].size);
  // P1-P2 is the far wall's top edge: the width is the reference's length.
  EXPECT_NEAR(rows[57].size->x, reference["length_m"].get<double>(), 0.01);
  EXPECT_EQ(rows[78].raw["camera"]["reference"]["length_m"], 4.5);
  EXPECT_NEAR(rows[78].size->x, 4.5, 0.01);
  EXPECT_NEAR(rows[88].raw["camera"]["reference"]["length_m"].get<double>(), reference["length_m"].get<double>(), 1e-12);
  EXPECT_NEAR(rows[88].size->x, rows[57].size->x, 1e-9);  // one undo step
  EXPECT_EQ(rows[96].raw["camera"]["reference"]["length_m"], 4.5);
  EXPECT_FALSE(rows[105].dirty);
  EXPECT_TRUE(fs::exists(dir_ / "camera.png"));

  auto text = readFile(dir_ / "turned.shot.json");
  ASSERT_TRUE(text) << text.message();
  const nlohmann::json saved = nlohmann::json::parse(*text);
  EXPECT_NEAR(saved.at("focal_mm").get<double>(), kFocalMm, 1e-9);
  EXPECT_NEAR(saved.at("sensor_width_mm").get<double>(), 6.4, 1e-9);
  EXPECT_EQ(saved.at("focal_source").get<std::string>().rfind("EXIF FocalLength", 0), 0u);
  EXPECT_EQ(saved.at("reference").at("from"), "P1");
  EXPECT_EQ(saved.at("reference").at("length_m"), 4.5);
  EXPECT_FALSE(saved.contains("camera_height_m"));
  EXPECT_FALSE(saved.contains("principal_point"));
}

TEST_F(EditCamera, ACrossedCornerIsRingedOnItsHandle) {
  const auto first = edit("cross_layout", "3 quit\n");
  ASSERT_GE(first.size(), 3u);
  const Row& r0 = first.back();
  // P6 dragged left past P5: the floor crosses itself.
  const glm::dvec2 p5 = r0.toWindow(r0.corners[4]), p6 = r0.toWindow(r0.corners[5]);
  Script s;
  s.drag(5, p6, {p5.x - p6.x - 60, 0});
  s.at(12, "capture warning.png");
  s.ctrlKeyHeld(14, "Z");
  s.at(22, "quit");
  const auto rows = edit("cross", s.str());
  ASSERT_GE(rows.size(), 22u);
  bool ringed = false;
  for (const auto& w : rows[11].raw["handle_warnings"]) {
    if (w["label"] != "crossed") continue;
    EXPECT_TRUE(w["blocking"].get<bool>());
    for (const auto& h : w["handles"]) ringed |= h == "P6";
  }
  EXPECT_TRUE(ringed) << rows[11].raw["handle_warnings"].dump();
  EXPECT_FALSE(rows[11].size);  // not measured
  ASSERT_EQ(rows[11].corners.size(), 8u);
  EXPECT_TRUE(rows[21].raw["handle_warnings"].empty()) << rows[21].raw["handle_warnings"].dump();
  // The capture shows the warning ring (red) around P6's new place.
  const cv::Mat capture = cv::imread((dir_ / "warning.png").string());
  ASSERT_FALSE(capture.empty());
  const glm::dvec2 at = rows[11].toWindow(rows[11].corners[5]);
  int red = 0;
  for (int dy = -15; dy <= 15; ++dy) {
    for (int dx = -15; dx <= 15; ++dx) {
      const int x = int(at.x) + dx, y = int(at.y) + dy;
      if (x < 0 || y < 0 || x >= capture.cols || y >= capture.rows) continue;
      const cv::Vec3b c = capture.at<cv::Vec3b>(y, x);
      red += c[2] > 200 && c[1] < 110 && c[0] < 100;
    }
  }
  EXPECT_GT(red, 20) << "no red ring around P6 in warning.png";
}

}  // namespace
}  // namespace pw::edit::test
