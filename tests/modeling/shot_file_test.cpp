// Shot files: what is read, and one-line errors for what is wrong in them.
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "modeling/shot_file.h"

namespace pw::modeling {
namespace {
namespace fs = std::filesystem;

class ShotFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("pw_shot_file_test_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    cv::imwrite((dir_ / "photo.png").string(), cv::Mat(60, 80, CV_8UC3, cv::Scalar(10, 20, 30)));
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }
  static std::string shot(const std::string& extra = "", const std::string& focal = "\"focal_px\": 70") {
    return "{\"image\": \"photo.png\", " + focal +
           ", \"camera_height_m\": 1.5, \"corners_px\": {\"P1\": [30, 20], \"P2\": [50, 20], \"P3\": [30, 40], "
           "\"P4\": [50, 40], \"P5\": [10, 55], \"P6\": [70, 55], \"P7\": [10, 5], \"P8\": [70, 5]}" +
           extra + "}";
  }
  // `text` with the first `from` replaced by `to`.
  static std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return at == std::string::npos ? text : text.replace(at, from.size(), to);
  }
  void expectError(const std::string& text, const std::string& needle) {
    auto loaded = loadShot(write("bad.json", text));
    ASSERT_FALSE(loaded.ok()) << text;
    EXPECT_NE(loaded.message().find(needle), std::string::npos) << loaded.message() << "\n" << text;
    EXPECT_EQ(loaded.message().find('\n'), std::string::npos);
  }
  fs::path dir_;
};

TEST_F(ShotFile, ReadsAGoodShot) {
  auto loaded = loadShot(write("good.json", shot(", \"reference\": {\"from\": \"P3\", \"to\": \"P4\", \"length_m\": 2}, \"extra\": 1")));
  ASSERT_TRUE(loaded.ok()) << loaded.message();
  EXPECT_EQ(loaded->shot.imageWidth, 80);
  EXPECT_EQ(loaded->shot.imageHeight, 60);
  EXPECT_DOUBLE_EQ(loaded->shot.focalPx, 70);
  EXPECT_DOUBLE_EQ(loaded->shot.cornersPx[metrology::P6].x, 70);
  ASSERT_TRUE(loaded->shot.reference.has_value());
  EXPECT_EQ(loaded->shot.reference->to, metrology::P4);
  EXPECT_DOUBLE_EQ(loaded->shot.principalPoint().x, 39.5);
}

TEST_F(ShotFile, FocalFromMillimetres) {
  auto loaded = loadShot(write("mm.json", shot("", "\"focal_mm\": 4, \"sensor_width_mm\": 8")));
  ASSERT_TRUE(loaded.ok()) << loaded.message();
  EXPECT_DOUBLE_EQ(loaded->shot.focalPx, 40);
}

TEST_F(ShotFile, ErrorsNameTheProblem) {
  expectError("{\"image\": ", "not valid JSON");
  expectError("[1, 2]", "JSON object");
  expectError(replaced(shot(), "photo.png", "nothere.png"), "does not exist");
  expectError(shot("", "\"focal_px\": \"wide\""), "must be a number");
  expectError(shot("", "\"focal_px\": 0"), "focal_px must be positive");
  expectError(shot("", "\"focal_px\": 1e999"), "number overflow");
  expectError(shot("", "\"focal_mm\": 4"), "sensor_width_mm");
  expectError(replaced(shot(), "\"P8\": [70, 5]", "\"P8\": [70, \"x\"]"), "corner P8");
  expectError(replaced(shot(), ", \"P8\": [70, 5]", ""), "no P8");
  expectError(shot(", \"reference\": {\"from\": 3, \"to\": \"P4\", \"length_m\": 2}"), "two different corners");
  expectError(shot(", \"image_size\": [800, 600]"), "does not match");
  expectError(replaced(shot(), "\"P6\": [70, 55]", "\"P6\": [700, 55]"), "far outside");
}

TEST_F(ShotFile, DistortionIsReadWrittenAndChecked) {
  auto plain = loadShot(write("plain.json", shot()));
  ASSERT_TRUE(plain.ok()) << plain.message();
  EXPECT_FALSE(plain->shot.distortion.has_value());  // absent: not known
  auto lens = loadShot(write("lens.json", shot(", \"distortion\": {\"k1\": -0.12, \"k2\": 0.01}")));
  ASSERT_TRUE(lens.ok()) << lens.message();
  ASSERT_TRUE(lens->shot.distortion.has_value());
  EXPECT_EQ(lens->shot.distortion->k1, -0.12);
  EXPECT_EQ(lens->shot.distortion->k2, 0.01);
  ASSERT_TRUE(writeShotFile(dir_ / "lens_copy.json", lens->shot).ok());
  auto again = loadShot(dir_ / "lens_copy.json");
  ASSERT_TRUE(again.ok()) << again.message();
  ASSERT_TRUE(again->shot.distortion.has_value());
  EXPECT_EQ(again->shot.distortion->k1, -0.12);
  EXPECT_EQ(again->shot.distortion->k2, 0.01);
  // A shot without one is written without one.
  ASSERT_TRUE(writeShotFile(dir_ / "plain_copy.json", plain->shot).ok());
  std::ifstream in(dir_ / "plain_copy.json");
  EXPECT_FALSE(nlohmann::json::parse(in).contains("distortion"));
  expectError(shot(", \"distortion\": -0.1"), "distortion must be {\"k1\"");
  expectError(shot(", \"distortion\": {\"k1\": \"wide\"}"), "must be a number");
  expectError(shot(", \"distortion\": {\"k3\": 0.1}"), "\"k3\" is not one of them");
  expectError(shot(", \"distortion\": {\"k1\": 7}"), "within -2..2");
}

TEST_F(ShotFile, WithoutAFocalLengthTheExifsOrAnError) {
  // photo.png has no EXIF: a shot without a focal length is refused, saying so; given
  // one (the command line's), it loads.
  expectError(shot("", "\"principal_point\": [39.5, 29.5]"), "no EXIF focal length");
  auto given = loadShot(write("given.json", shot("", "\"principal_point\": [39.5, 29.5]")), 65.0);
  ASSERT_TRUE(given.ok()) << given.message();
  EXPECT_EQ(given->shot.focalPx, 65.0);
  EXPECT_EQ(given->focalSource, "given");
  auto own = loadShot(write("own.json", shot(", \"focal_source\": \"set in the editor\"")));
  ASSERT_TRUE(own.ok());
  EXPECT_EQ(own->focalSource, "set in the editor");
}

TEST_F(ShotFile, BrokenImagesAreErrors) {
  std::ofstream(dir_ / "empty.png").close();
  std::ofstream(dir_ / "junk.png") << "this is not a png";
  expectError(replaced(shot(), "photo.png", "empty.png"), "is empty");
  expectError(replaced(shot(), "photo.png", "junk.png"), "not a readable");
}

TEST_F(ShotFile, WriteThenReadGivesTheSameShot) {
  auto loaded = loadShot(write("good.json", shot()));
  ASSERT_TRUE(loaded.ok());
  ASSERT_TRUE(writeShotFile(dir_ / "copy.json", loaded->shot).ok());
  auto again = loadShot(dir_ / "copy.json");
  ASSERT_TRUE(again.ok()) << again.message();
  EXPECT_EQ(again->shot.imagePath, loaded->shot.imagePath);
  for (int i = 0; i < metrology::kCornerCount; ++i) EXPECT_EQ(again->shot.cornersPx[i], loaded->shot.cornersPx[i]);
}

TEST_F(ShotFile, AnImagePathWithANulIsRefused) {
  // Found by modeling/fuzz/shot_fuzz: it was read, and written back as another path.
  expectError(replaced(shot(), "\"photo.png\"", "\"\\u0000or.png\""), "field \"image\" holds a NUL character");
}

TEST_F(ShotFile, AShotWithoutAFocalLengthIsWrittenWithoutOne) {
  // Read without one (the EXIF's is taken when the photo is loaded), it was written
  // back as "focal_px": 0, which no reader takes (found by modeling/fuzz/shot_fuzz).
  auto read = readShotFile(write("nofocal.json", shot("", "\"principal_point\": [39.5, 29.5]")));
  ASSERT_TRUE(read.ok()) << read.message();
  ASSERT_TRUE(writeShotFile(dir_ / "copy.json", *read).ok());
  auto again = readShotFile(dir_ / "copy.json");
  ASSERT_TRUE(again.ok()) << again.message();
  EXPECT_EQ(*again, *read);
}

// Fields photowalk does not read (a detection report, ground truth, a note) survive a
// read and write; the shot's own fields are written from the shot.
TEST_F(ShotFile, FieldsPhotowalkDoesNotReadSurviveAWrite) {
  auto loaded = loadShot(write("extra.json", shot(", \"detection\": {\"confidence\": 0.9}, \"note\": \"hall\"")));
  ASSERT_TRUE(loaded.ok()) << loaded.message();
  EXPECT_EQ(loaded->otherFields, nlohmann::json::parse(R"({"detection": {"confidence": 0.9}, "note": "hall"})"));
  loaded->shot.cornersPx[0].x = 31;
  ASSERT_TRUE(writeShotFile(dir_ / "extra_copy.json", loaded->shot, loaded->otherFields).ok());
  std::ifstream in(dir_ / "extra_copy.json");
  const nlohmann::json written = nlohmann::json::parse(in);
  EXPECT_EQ(written.at("detection").at("confidence"), 0.9);
  EXPECT_EQ(written.at("note"), "hall");
  EXPECT_EQ(written.at("corners_px").at("P1")[0], 31.0);
  // A field of the shot's own in otherFields is replaced, not kept.
  ASSERT_TRUE(writeShotFile(dir_ / "extra_copy2.json", loaded->shot, nlohmann::json{{"focal_px", 1}}).ok());
  auto again = loadShot(dir_ / "extra_copy2.json");
  ASSERT_TRUE(again.ok()) << again.message();
  EXPECT_EQ(again->shot.focalPx, 70.0);
  EXPECT_TRUE(again->otherFields.empty());
}

// A focal length given in millimetres stays in millimetres (with the sensor width)
// when the shot is written back, and means the same number of pixels.
TEST_F(ShotFile, FocalInMillimetresSurvivesAWrite) {
  auto loaded = loadShot(write("mm.json", shot("", "\"focal_mm\": 24, \"sensor_width_mm\": 36")));
  ASSERT_TRUE(loaded.ok()) << loaded.message();
  ASSERT_TRUE(writeShotFile(dir_ / "mm_copy.json", loaded->shot).ok());
  std::ifstream in(dir_ / "mm_copy.json");
  const nlohmann::json written = nlohmann::json::parse(in);
  EXPECT_EQ(written.at("focal_mm"), 24.0);
  EXPECT_EQ(written.at("sensor_width_mm"), 36.0);
  EXPECT_FALSE(written.contains("focal_px"));
  auto again = loadShot(dir_ / "mm_copy.json");
  ASSERT_TRUE(again.ok()) << again.message();
  EXPECT_DOUBLE_EQ(again->shot.focalPx, 24.0 / 36.0 * loaded->shot.imageWidth);
  EXPECT_DOUBLE_EQ(again->shot.focalPx, loaded->shot.focalPx);
}

}  // namespace
}  // namespace pw::modeling
