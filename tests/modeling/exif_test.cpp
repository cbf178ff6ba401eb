// modeling/exif.h: JPEGs written here with EXIF blocks built by libexif, each tag path,
// no EXIF, corrupt blocks, and the orientation applied to the pixels and the sensor axes.
#include "modeling/exif.h"

#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "tests/support/exif_jpeg.h"

namespace pw::modeling {
namespace {
namespace fs = std::filesystem;
using test::ExifFields;

fs::path outDir() {
  const fs::path dir = fs::path(PW_BINARY_DIR) / "test-output" / "exif";
  fs::create_directories(dir);
  return dir;
}

// A 640 x 480 photo whose stored top-left quarter-corner is red and top-right green, so
// that an orientation shows where it put them.
cv::Mat storedPhoto(int width = 640, int height = 480) {
  cv::Mat image(height, width, CV_8UC3, cv::Scalar(90, 90, 90));
  image(cv::Rect(0, 0, width / 4, height / 4)).setTo(cv::Scalar(0, 0, 255));
  image(cv::Rect(width - width / 4, 0, width / 4, height / 4)).setTo(cv::Scalar(0, 255, 0));
  return image;
}

fs::path writeJpeg(const std::string& name, const std::vector<unsigned char>& app1, const cv::Mat& image = storedPhoto()) {
  const fs::path path = outDir() / (name + ".jpg");
  test::writeBytes(path, test::jpegWithApp1(image, app1));
  return path;
}

// A 4.2 mm lens on a 6.4 x 4.8 mm sensor: 100 px/mm at 640 x 480, so 420 px.
ExifFields phoneFields() {
  ExifFields f;
  f.make = "Photowalk";
  f.model = "Test Phone 1";
  f.focalLength = {42, 10};
  f.focalPlaneXResolution = {1000, 1};  // px per cm
  f.focalPlaneYResolution = {1000, 1};
  f.focalPlaneResolutionUnit = 3;
  return f;
}

TEST(Exif, FocalLengthWithFocalPlaneResolutionGivesTheSensorAndPixels) {
  auto photo = readPhoto(writeJpeg("plane_cm", test::exifBlock(phoneFields())));
  ASSERT_TRUE(photo) << photo.message();
  EXPECT_TRUE(photo->exif.present);
  EXPECT_EQ(photo->exif.make, "Photowalk");
  EXPECT_EQ(photo->exif.model, "Test Phone 1");
  ASSERT_TRUE(photo->exif.focalLengthMm);
  EXPECT_DOUBLE_EQ(*photo->exif.focalLengthMm, 4.2);
  ASSERT_TRUE(photo->focal) << (photo->notes.empty() ? "" : photo->notes[0]);
  EXPECT_NEAR(photo->focal->focalPx, 420.0, 1e-9);
  ASSERT_TRUE(photo->focal->focalMm);
  EXPECT_DOUBLE_EQ(photo->focal->focalMm->focalMm, 4.2);
  EXPECT_NEAR(photo->focal->focalMm->sensorWidthMm, 6.4, 1e-12);
  EXPECT_NEAR(*photo->focal->sensorHeightMm, 4.8, 1e-12);
  EXPECT_NE(photo->focal->source.find("EXIF FocalLength 4.20 mm with FocalPlaneXResolution 1000.0 px/cm"),
            std::string::npos)
      << photo->focal->source;
  EXPECT_TRUE(photo->notes.empty());
}

TEST(Exif, FocalPlaneResolutionInInchesTheDefaultUnit) {
  ExifFields f = phoneFields();
  f.focalPlaneXResolution = f.focalPlaneYResolution = std::pair<unsigned, unsigned>{2540, 1};  // 100 px/mm
  f.focalPlaneResolutionUnit.reset();  // absent: inches
  auto photo = readPhoto(writeJpeg("plane_inch", test::exifBlock(f)));
  ASSERT_TRUE(photo && photo->focal);
  EXPECT_NEAR(photo->focal->focalPx, 420.0, 1e-9);
  EXPECT_NE(photo->focal->source.find("px/inch"), std::string::npos);
}

TEST(Exif, PixelDimensionsGiveTheSensorOfAResizedPhoto) {
  // The camera wrote 640 x 480 (100 px/mm); the file holds it resized to 320 x 240.
  ExifFields f = phoneFields();
  f.pixelXDimension = 640;
  f.pixelYDimension = 480;
  auto photo = readPhoto(writeJpeg("resized", test::exifBlock(f), storedPhoto(320, 240)));
  ASSERT_TRUE(photo && photo->focal);
  EXPECT_NEAR(photo->focal->focalMm->sensorWidthMm, 6.4, 1e-12);
  EXPECT_NEAR(photo->focal->focalPx, 210.0, 1e-9);
}

TEST(Exif, FocalLengthIn35mmFilmByTheDiagonal) {
  ExifFields f;
  f.focalLength35mm = 28;
  auto photo = readPhoto(writeJpeg("f35", test::exifBlock(f)));
  ASSERT_TRUE(photo && photo->focal);
  EXPECT_NEAR(photo->focal->focalPx, 28.0 / std::hypot(36.0, 24.0) * 800.0, 1e-9);  // 640 x 480: 800 px across
  EXPECT_FALSE(photo->focal->focalMm);
  EXPECT_NE(photo->focal->source.find("EXIF FocalLengthIn35mmFilm 28 mm"), std::string::npos);
}

TEST(Exif, TheSensorSizeIsPreferredToThe35mmEquivalent) {
  ExifFields f = phoneFields();
  f.focalLength35mm = 50;
  auto photo = readPhoto(writeJpeg("both", test::exifBlock(f)));
  ASSERT_TRUE(photo && photo->focal);
  EXPECT_NEAR(photo->focal->focalPx, 420.0, 1e-9);
}

TEST(Exif, FocalLengthAloneSaysTheSensorIsNeeded) {
  ExifFields f;
  f.focalLength = {50, 1};
  auto photo = readPhoto(writeJpeg("focal_only", test::exifBlock(f)));
  ASSERT_TRUE(photo);
  EXPECT_FALSE(photo->focal);
  ASSERT_EQ(photo->notes.size(), 1u);
  EXPECT_NE(photo->notes[0].find("no sensor size"), std::string::npos) << photo->notes[0];
}

TEST(Exif, ImplausibleSensorIsIgnoredWithANote) {
  ExifFields f = phoneFields();
  f.focalPlaneXResolution = f.focalPlaneYResolution = std::pair<unsigned, unsigned>{1, 1};  // 640 cm wide
  auto photo = readPhoto(writeJpeg("implausible", test::exifBlock(f)));
  ASSERT_TRUE(photo);
  EXPECT_FALSE(photo->focal);
  ASSERT_FALSE(photo->notes.empty());
  EXPECT_NE(photo->notes[0].find("implausible"), std::string::npos) << photo->notes[0];
}

TEST(Exif, ZeroDenominatorIsUnset) {
  ExifFields f = phoneFields();
  f.focalLength = {42, 0};
  auto photo = readPhoto(writeJpeg("zero_denominator", test::exifBlock(f)));
  ASSERT_TRUE(photo);
  EXPECT_FALSE(photo->exif.focalLengthMm);
  EXPECT_FALSE(photo->focal);
}

TEST(Exif, APhotoWithoutExif) {
  auto photo = readPhoto(writeJpeg("no_exif", {}));
  ASSERT_TRUE(photo) << photo.message();
  EXPECT_FALSE(photo->exif.present);
  EXPECT_FALSE(photo->focal);
  EXPECT_TRUE(photo->notes.empty());
  EXPECT_EQ(photo->bgr.cols, 640);
  EXPECT_EQ(photo->bgr.rows, 480);
  const fs::path png = outDir() / "no_exif.png";
  cv::imwrite(png.string(), storedPhoto());
  auto fromPng = readPhoto(png);
  ASSERT_TRUE(fromPng);
  EXPECT_FALSE(fromPng->exif.present);
  EXPECT_EQ(fromPng->bgr.cols, 640);
}

TEST(Exif, CorruptBlocksNeverCrashAndGiveNoFocal) {
  const std::vector<std::vector<unsigned char>> blocks = {
      // a TIFF header whose IFD offset points far beyond the block
      {'E', 'x', 'i', 'f', 0, 0, 'I', 'I', 42, 0, 0xF0, 0xFF, 0xFF, 0x0F},
      // IFD 0 claims 65535 entries in 10 bytes
      {'E', 'x', 'i', 'f', 0, 0, 'I', 'I', 42, 0, 8, 0, 0, 0, 0xFF, 0xFF, 1, 2, 3, 4},
      // not TIFF at all
      {'E', 'x', 'i', 'f', 0, 0, 'X', 'X', 1, 2, 3, 4, 5, 6, 7, 8},
      // only the header
      {'E', 'x', 'i', 'f', 0, 0},
  };
  for (size_t i = 0; i < blocks.size(); ++i) {
    auto photo = readPhoto(writeJpeg("corrupt_" + std::to_string(i), blocks[i]));
    ASSERT_TRUE(photo) << i << ": " << photo.message();
    EXPECT_FALSE(photo->focal) << i;
    EXPECT_EQ(photo->exif.orientation, 1) << i;
    EXPECT_EQ(photo->bgr.cols, 640) << i;
  }
  // A real block cut short: what was read is kept, and the file still opens.
  std::vector<unsigned char> cut = test::exifBlock(phoneFields());
  cut.resize(cut.size() * 2 / 3);
  auto photo = readPhoto(writeJpeg("corrupt_cut", cut));
  ASSERT_TRUE(photo) << photo.message();
  EXPECT_EQ(photo->bgr.cols, 640);
  if (photo->focal) {
    EXPECT_TRUE(std::isfinite(photo->focal->focalPx) && photo->focal->focalPx > 0);
  }
  // Bytes that no file holds: every length of a block's prefix.
  const std::vector<unsigned char> full = test::exifBlock(phoneFields());
  for (size_t n = 0; n <= full.size(); ++n) {
    const ExifTags tags = readExifBytes(full.data(), n);
    if (auto f = exifFocal(tags, 640, 480)) {
      EXPECT_TRUE(std::isfinite(f->focalPx) && f->focalPx > 0) << n;
    }
  }
}

TEST(Exif, Orientation6RotatesThePhotoAndSwapsTheSensorAxes) {
  ExifFields f = phoneFields();
  f.orientation = 6;
  const fs::path path = writeJpeg("orientation6", test::exifBlock(f));
  auto photo = readPhoto(path);
  ASSERT_TRUE(photo) << photo.message();
  EXPECT_EQ(photo->exif.orientation, 6);
  // Shown portrait: 480 wide, 640 high; the stored top-left (red) is now top-right.
  ASSERT_EQ(photo->bgr.cols, 480);
  ASSERT_EQ(photo->bgr.rows, 640);
  EXPECT_GT(photo->bgr.at<cv::Vec3b>(10, 470)[2], 200);  // red, within JPEG's loss
  EXPECT_LT(photo->bgr.at<cv::Vec3b>(10, 470)[1], 40);
  // The sensor turned with it: 4.8 mm across the shown photo, the same 100 px per mm.
  ASSERT_TRUE(photo->focal && photo->focal->focalMm);
  EXPECT_NEAR(photo->focal->focalMm->sensorWidthMm, 4.8, 1e-12);
  EXPECT_NEAR(*photo->focal->sensorHeightMm, 6.4, 1e-12);
  EXPECT_NEAR(photo->focal->focalPx, 420.0, 1e-9);
  EXPECT_NEAR(photo->focal->focalMm->pixels(photo->bgr.cols), 420.0, 1e-9);
  EXPECT_NE(photo->focal->source.find("(sensor 4.80 x 6.40 mm, turned with the photo)"), std::string::npos)
      << photo->focal->source;
}

TEST(Exif, EveryOrientationAgreesWithOpenCv) {
  for (int orientation = 1; orientation <= 8; ++orientation) {
    ExifFields f;
    f.orientation = orientation;
    f.focalLength35mm = 28;
    const fs::path path = writeJpeg("orientation" + std::to_string(orientation) + "_cv", test::exifBlock(f));
    auto photo = readPhoto(path);
    ASSERT_TRUE(photo) << orientation;
    const cv::Mat byOpenCv = cv::imread(path.string(), cv::IMREAD_COLOR);
    ASSERT_EQ(photo->bgr.size(), byOpenCv.size()) << orientation;
    EXPECT_EQ(cv::norm(photo->bgr, byOpenCv, cv::NORM_INF), 0.0) << orientation;
    EXPECT_EQ(orientationSwapsAxes(orientation), orientation >= 5) << orientation;
    // The 35 mm equivalent goes by the diagonal: the same whatever the orientation.
    ASSERT_TRUE(photo->focal);
    EXPECT_NEAR(photo->focal->focalPx, 28.0 / std::hypot(36.0, 24.0) * 800.0, 1e-9);
  }
}

TEST(Exif, OrientationOutOfRangeIsIgnored) {
  ExifFields f;
  f.orientation = 9;
  auto photo = readPhoto(writeJpeg("orientation9", test::exifBlock(f)));
  ASSERT_TRUE(photo);
  EXPECT_EQ(photo->exif.orientation, 1);
  EXPECT_EQ(photo->bgr.cols, 640);
  ASSERT_FALSE(photo->notes.empty());
  EXPECT_NE(photo->notes[0].find("Orientation 9"), std::string::npos);
}

TEST(Exif, AMissingFileIsAnError) {
  auto photo = readPhoto(outDir() / "no_such_photo.jpg");
  ASSERT_FALSE(photo);
  EXPECT_NE(photo.message().find("no_such_photo.jpg"), std::string::npos);
}

}  // namespace
}  // namespace pw::modeling
