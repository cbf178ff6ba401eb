// The document's camera from a photo's EXIF, without a window: the focal length and
// its source, what Save writes, undo, and a photo stored on its side (orientation 6)
// whose corners and focal length agree with the upright scene.
#include <filesystem>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "base/atomic_file.h"
#include "editor/edit/document.h"
#include "tests/support/exif_jpeg.h"
#include "tests/support/groundtruth.h"

namespace pw::edit {
namespace {
namespace fs = std::filesystem;
using metrology::Shot;

// Its own folder: edit.Camera (camera_window_test.cpp) empties "edit_camera" as it starts,
// and ctest runs the two at once.
fs::path outputDir() {
  const fs::path dir = fs::path(PW_BINARY_DIR) / "test-output" / "edit_camera_document";
  fs::create_directories(dir);
  return dir;
}

// corridor_b (1024 x 768, focal 803.679 px) as taken by a camera with a 6.4 x 4.8 mm
// sensor: 160 px/mm (1600 px/cm), so a 5.02299 mm lens.
constexpr double kFocalMm = 5.02299;
constexpr double kPxPerMm = 160.0;

test::ExifFields corridorExif(int orientation) {
  test::ExifFields f;
  f.make = "Photowalk";
  f.model = "Corridor Cam";
  f.orientation = orientation;
  f.focalLength = {unsigned(kFocalMm * 100000 + 0.5), 100000};
  f.focalPlaneXResolution = f.focalPlaneYResolution = std::pair<unsigned, unsigned>{1600, 1};
  f.focalPlaneResolutionUnit = 3;
  return f;
}

fs::path corridorJpeg(const std::string& name, int orientation, const cv::Mat& stored) {
  const fs::path path = outputDir() / (name + ".jpg");
  test::writeBytes(path, test::jpegWithApp1(stored, test::exifBlock(corridorExif(orientation))));
  return path;
}

nlohmann::json readJson(const fs::path& path) {
  auto text = readFile(path);
  return text ? nlohmann::json::parse(*text) : nlohmann::json();
}

TEST(CameraDocument, APhotoAloneTakesItsFocalLengthFromExif) {
  const groundtruth::GroundTruth truth = groundtruth::loadGroundTruth("corridor_b");
  const fs::path jpeg = corridorJpeg("corridor_exif", 1, cv::imread(truth.image.string()));
  auto doc = Document::open(jpeg);
  ASSERT_TRUE(doc) << doc.message();
  const Shot& shot = doc->shot();
  EXPECT_NEAR(shot.focalPx, kFocalMm * kPxPerMm, 1e-9);
  ASSERT_TRUE(shot.focalMm);
  EXPECT_NEAR(shot.focalMm->focalMm, kFocalMm, 1e-9);
  EXPECT_NEAR(shot.focalMm->sensorWidthMm, 6.4, 1e-12);
  EXPECT_EQ(doc->exif().model, "Corridor Cam");
  EXPECT_EQ(doc->focalSource().rfind("EXIF FocalLength 5.02 mm with FocalPlaneXResolution 1600.0 px/cm", 0), 0u)
      << doc->focalSource();
  bool noted = false;
  for (const std::string& note : doc->notes()) noted |= note.find("px from the photo's EXIF") != std::string::npos;
  EXPECT_TRUE(noted);

  // Saved: in mm with the sensor, and where it came from.
  ASSERT_TRUE(doc->save()) << "save";
  nlohmann::json saved = readJson(doc->path());
  EXPECT_NEAR(saved.at("focal_mm").get<double>(), kFocalMm, 1e-9);
  EXPECT_NEAR(saved.at("sensor_width_mm").get<double>(), 6.4, 1e-12);
  EXPECT_EQ(saved.at("focal_source").get<std::string>(), doc->focalSource());

  // Set by hand, then undone: the source follows.
  Shot edited = shot;
  edited.focalMm->focalMm = 6.0;
  edited.focalPx = edited.focalMm->pixels(edited.imageWidth);
  doc->apply(edited, "focal length");
  EXPECT_EQ(doc->focalSource(), "set in the editor");
  const fs::path copy = outputDir() / "corridor_exif_by_hand.json";
  ASSERT_TRUE(doc->saveCopy(copy));
  EXPECT_EQ(readJson(copy).at("focal_source").get<std::string>(), "set in the editor");
  doc->undo();
  EXPECT_EQ(doc->focalSource().rfind("EXIF FocalLength", 0), 0u);
  // In px, the same pixels: still the EXIF's.
  Shot inPx = doc->shot();
  inPx.focalMm.reset();
  doc->apply(inPx, "focal length unit");
  EXPECT_EQ(doc->focalSource().rfind("EXIF FocalLength", 0), 0u);
  doc->undo();

  // The saved shot reopened: the same source, and saved again byte for byte.
  const std::string bytes = *readFile(doc->path());
  auto reopened = Document::open(doc->path());
  ASSERT_TRUE(reopened) << reopened.message();
  EXPECT_EQ(reopened->focalSource(), doc->focalSource());
  EXPECT_TRUE(reopened->exif().present);
  ASSERT_TRUE(reopened->save());
  EXPECT_EQ(*readFile(doc->path()), bytes);
}

TEST(CameraDocument, APhotoStoredOnItsSideIsShownUprightWithTheSensorTurned) {
  const groundtruth::GroundTruth truth = groundtruth::loadGroundTruth("corridor_b");
  // Stored turned 90 degrees anticlockwise; Orientation 6 says to turn it clockwise.
  cv::Mat stored;
  cv::rotate(cv::imread(truth.image.string()), stored, cv::ROTATE_90_COUNTERCLOCKWISE);
  ASSERT_EQ(stored.cols, 768);
  auto doc = Document::open(corridorJpeg("corridor_exif_turned", 6, stored));
  ASSERT_TRUE(doc) << doc.message();
  ASSERT_EQ(doc->photo().cols, 1024);
  ASSERT_EQ(doc->photo().rows, 768);
  const Shot& shot = doc->shot();
  ASSERT_TRUE(shot.focalMm);
  // The stored image's y axis is the photo's x: the 6.4 mm side is across it again.
  EXPECT_NEAR(shot.focalMm->sensorWidthMm, 6.4, 1e-12);
  EXPECT_NEAR(shot.focalPx, kFocalMm * kPxPerMm, 1e-9);
  EXPECT_NEAR(shot.focalPx, truth.focalPx, 0.01);
  // Detection, given that focal length, finds the upright corridor's far wall (P5..P8
  // go to the photo's edge by default, not to the scene's painted band, the answers').
  for (int k = 0; k < metrology::P5; ++k) {
    EXPECT_LT(glm::length(shot.cornersPx[k] - truth.cornersPx[k]), 1.0) << metrology::cornerName(k);
  }
  for (int k = metrology::P5; k <= metrology::P8; ++k) {
    EXPECT_TRUE(shot.cornersPx[k].x >= 0 && shot.cornersPx[k].y >= 0 && shot.cornersPx[k].x <= 1023 &&
                shot.cornersPx[k].y <= 767)
        << metrology::cornerName(k);
  }
  EXPECT_NE(doc->focalSource().find("turned with the photo"), std::string::npos) << doc->focalSource();
}

TEST(CameraDocument, APhotoWithoutExifSaysItsFocalLengthIsTheDefault) {
  const groundtruth::GroundTruth truth = groundtruth::loadGroundTruth("corridor_b");
  auto doc = Document::open(truth.image);
  ASSERT_TRUE(doc) << doc.message();
  EXPECT_FALSE(doc->exif().present);
  EXPECT_FALSE(doc->exifFocal());
  // A corridor seen straight down has no second vanishing point: the default lens,
  // 819.2 px here, where the EXIF above gave the camera's 803.68 px.
  EXPECT_EQ(doc->focalSource(), "default: a 28 mm-equivalent lens");
  EXPECT_NEAR(doc->shot().focalPx, 0.8 * 1024, 1e-9);
  // The measurement's ± carries both assumptions until they are set (issue 23).
  metrology::InputOrigins origins = doc->inputOrigins();
  EXPECT_EQ(origins.focal, metrology::FocalOrigin::kAssumed);
  EXPECT_TRUE(origins.cameraHeightAssumed);
  metrology::Shot set = doc->shot();
  set.focalPx = 803.68;
  set.cameraHeightM = 1.5;
  doc->apply(set, "camera");
  origins = doc->inputOrigins();
  EXPECT_EQ(origins.focal, metrology::FocalOrigin::kGiven) << doc->focalSource();
  EXPECT_FALSE(origins.cameraHeightAssumed);
}

}  // namespace
}  // namespace pw::edit
