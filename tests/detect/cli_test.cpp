// `photowalk detect` end to end: the shot it writes is read by `photowalk measure`;
// an unsure corridor is exit 3 with a warning; no corridor is exit 2 with nothing
// written; bad input is exit 1 with one line.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "tests/detect/corridor_cases.h"
#include "tests/detect/synthetic_corridor.h"
#include "tests/support/exif_jpeg.h"

namespace {
namespace fs = std::filesystem;

struct CommandRun {
  int exitCode = -1;
  std::string out, err;
};

class DetectCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    binary_ = fs::path(PW_BINARY_DIR) / "photowalk";
    ASSERT_TRUE(fs::exists(binary_)) << binary_ << " is not built";
    dir_ = fs::temp_directory_path() / ("pw_detect_cli_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    if (!dir_.empty()) fs::remove_all(dir_, ec);
  }
  CommandRun run(const std::string& arguments) {
    const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    const std::string command = binary_.string() + " " + arguments + " >" + out.string() + " 2>" + err.string();
    const int status = std::system(command.c_str());
    CommandRun r;
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
  }
  static std::string slurp(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  fs::path binary_, dir_;
};

TEST_F(DetectCommand, WritesAShotThatMeasureReads) {
  const auto cases = pw::metrology::detect::testing::loadCorridorCases();
  const auto& c = cases[0];
  const fs::path shot = dir_ / "shot.json", overlay = dir_ / "overlay.png";
  const CommandRun detect = run("detect " + c.imagePath + " --focal-px " + std::to_string(c.focalPx) + " --camera-height " +
                         std::to_string(c.cameraHeightM) + " -o " + shot.string() + " --overlay " + overlay.string());
  ASSERT_EQ(detect.exitCode, 0) << detect.err;
  const nlohmann::json doc = nlohmann::json::parse(slurp(shot));
  EXPECT_TRUE(fs::path(doc["image"].get<std::string>()).is_relative());
  for (int k = 1; k <= 8; ++k) {
    const std::string name = "P" + std::to_string(k);
    ASSERT_TRUE(doc["corners_px"].contains(name)) << name;
    const double confidence = doc["detection"]["corners"][name]["confidence"];
    EXPECT_TRUE(confidence >= 0 && confidence <= 1) << name;
    // Where detection put it (the editor shows its confidence while it is there).
    EXPECT_EQ(doc["detection"]["corners"][name]["px"], doc["corners_px"][name]) << name;
  }
  EXPECT_EQ(doc["detection"]["focal_source"], "given");
  EXPECT_GT(doc["detection"]["vanishing_points"]["corridor"]["confidence"].get<double>(), 0.5);
  const cv::Mat drawn = cv::imread(overlay.string());
  EXPECT_EQ(drawn.cols, c.image.cols);

  const CommandRun measure = run("measure " + shot.string());
  ASSERT_EQ(measure.exitCode, 0) << measure.err;
  const nlohmann::json m = nlohmann::json::parse(measure.out);
  EXPECT_NEAR(m["width_m"].get<double>(), c.widthM, 0.02 * c.widthM);
  EXPECT_NEAR(m["height_m"].get<double>(), c.heightM, 0.02 * c.heightM);
}

// Without --focal-px, the photo's EXIF focal length (modeling/exif.h, the editor's
// code) is the one detect uses: the same corners as with that focal length given, the
// shot in the EXIF's millimetres with its source; a photo without EXIF does not say EXIF.
TEST_F(DetectCommand, UsesTheExifFocalLengthWhenNoneIsGiven) {
  const auto cases = pw::metrology::detect::testing::loadCorridorCases();
  const auto& c = cases[0];
  constexpr double kPxPerMm = 160.0;  // FocalPlaneXResolution 1600 px/cm
  const double focalMm = c.focalPx / kPxPerMm;
  pw::test::ExifFields f;
  f.focalLength = {unsigned(focalMm * 100000 + 0.5), 100000};
  f.focalPlaneXResolution = f.focalPlaneYResolution = std::pair<unsigned, unsigned>{1600, 1};
  f.focalPlaneResolutionUnit = 3;  // cm
  const fs::path withExif = dir_ / "exif.jpg", without = dir_ / "plain.jpg";
  pw::test::writeBytes(withExif, pw::test::jpegWithApp1(c.image, pw::test::exifBlock(f)));
  ASSERT_TRUE(cv::imwrite(without.string(), c.image, {cv::IMWRITE_JPEG_QUALITY, 95}));
  const double exifFocalPx = double(unsigned(focalMm * 100000 + 0.5)) / 100000 * kPxPerMm;

  const fs::path fromExif = dir_ / "exif.json", given = dir_ / "given.json", plain = dir_ / "plain.json";
  const std::string height = " --camera-height " + std::to_string(c.cameraHeightM);
  const CommandRun a = run("detect " + withExif.string() + height + " -o " + fromExif.string());
  ASSERT_EQ(a.exitCode, 0) << a.err;
  std::ostringstream focalText;
  focalText.precision(17);
  focalText << exifFocalPx;
  const CommandRun b = run("detect " + withExif.string() + height + " --focal-px " + focalText.str() + " -o " + given.string());
  ASSERT_EQ(b.exitCode, 0) << b.err;
  const CommandRun p = run("detect " + without.string() + height + " -o " + plain.string());
  ASSERT_EQ(p.exitCode, 0) << p.err;

  const nlohmann::json e = nlohmann::json::parse(slurp(fromExif)), g = nlohmann::json::parse(slurp(given));
  EXPECT_EQ(e["focal_source"].get<std::string>().rfind("EXIF FocalLength", 0), 0u) << e.dump();
  EXPECT_EQ(e["detection"]["focal_source"], "exif");
  EXPECT_NEAR(e["focal_mm"].get<double>(), exifFocalPx / kPxPerMm, 1e-9);
  EXPECT_NEAR(e["sensor_width_mm"].get<double>(), c.image.cols / kPxPerMm, 1e-9);
  EXPECT_EQ(e["corners_px"], g["corners_px"]);  // the very detection of the focal length given
  EXPECT_NE(a.out.find("EXIF FocalLength"), std::string::npos) << a.out;
  const nlohmann::json n = nlohmann::json::parse(slurp(plain));
  EXPECT_EQ(n["focal_source"].get<std::string>().find("EXIF"), std::string::npos) << n["focal_source"];

  const CommandRun measure = run("measure " + fromExif.string());
  ASSERT_EQ(measure.exitCode, 0) << measure.err;
  const nlohmann::json m = nlohmann::json::parse(measure.out);
  EXPECT_NEAR(m["width_m"].get<double>(), c.widthM, 0.01 * c.widthM);
  EXPECT_NEAR(m["height_m"].get<double>(), c.heightM, 0.01 * c.heightM);
}

// An unsure best guess (clutter_8: the far wall's foot hidden by a cabinet and a
// person) is written for a person to check: exit 3, one warning line saying why,
// and the shot's detection says it too.
TEST_F(DetectCommand, UnsureIsExitThreeWithAWarningAndTheShotWritten) {
  const auto cases = pw::metrology::detect::testing::loadCorridorCases({"clutter_8"});
  const auto& c = cases[0];
  const fs::path shot = dir_ / "shot.json";
  const CommandRun r = run("detect " + c.imagePath + " --focal-px " + std::to_string(c.focalPx) + " -o " + shot.string());
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_NE(r.err.find("warning: unsure of this corridor"), std::string::npos) << r.err;
  ASSERT_TRUE(fs::exists(shot));
  const nlohmann::json doc = nlohmann::json::parse(slurp(shot));
  EXPECT_FALSE(doc["detection"]["confident"].get<bool>());
  EXPECT_FALSE(doc["detection"]["doubts"].empty());
  // A confident detection says so too.
  const auto clean = pw::metrology::detect::testing::loadCorridorCases({"corridor_a"});
  const CommandRun sure = run("detect " + clean[0].imagePath + " --focal-px " + std::to_string(clean[0].focalPx) +
                              " -o " + shot.string());
  ASSERT_EQ(sure.exitCode, 0) << sure.err;
  EXPECT_TRUE(nlohmann::json::parse(slurp(shot))["detection"]["confident"].get<bool>());
}

TEST_F(DetectCommand, NoCorridorIsExitTwoAndWritesNothing) {
  const fs::path photo = dir_ / "blank.png", shot = dir_ / "shot.json";
  ASSERT_TRUE(cv::imwrite(photo.string(), cv::Mat(480, 640, CV_8UC3, cv::Scalar(120, 130, 140))));
  const CommandRun r = run("detect " + photo.string() + " -o " + shot.string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("no corridor found"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(shot));
  // Nor any temporary file beside it.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 3);  // photo, stdout, stderr
}

// A photo with vanishing points but no corridor's box (a road to the horizon): exit 2,
// the points printed and written without corners; measure refuses the file, naming
// the editor as the way on.
TEST_F(DetectCommand, NoBoxButVanishingPointsIsExitTwoWithThePointsWritten) {
  const fs::path photo = dir_ / "road.png", shot = dir_ / "shot.json";
  ASSERT_TRUE(cv::imwrite(photo.string(), pw::metrology::detect::testing::drawRoadScene()));
  const CommandRun r = run("detect " + photo.string() + " --focal-px 700 -o " + shot.string());
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("no corridor found"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("vanishing points"), std::string::npos) << r.out;
  ASSERT_TRUE(fs::exists(shot));
  const nlohmann::json doc = nlohmann::json::parse(slurp(shot));
  EXPECT_FALSE(doc.contains("corners_px"));
  EXPECT_FALSE(doc["detection"]["found"].get<bool>());
  EXPECT_FALSE(doc["detection"]["reason"].get<std::string>().empty());
  const auto& px = doc["detection"]["vanishing_points"]["corridor"]["px"];
  EXPECT_NEAR(px[0].get<double>(), pw::metrology::detect::testing::kRoadVanishingPoint.x, 3.0);
  EXPECT_NEAR(px[1].get<double>(), pw::metrology::detect::testing::kRoadVanishingPoint.y, 3.0);
  for (const char* role : {"horizontal", "vertical"}) EXPECT_TRUE(doc["detection"]["vanishing_points"].contains(role));
  const CommandRun measure = run("measure " + shot.string());
  EXPECT_EQ(measure.exitCode, 1);
  EXPECT_NE(measure.err.find("photowalk edit"), std::string::npos) << measure.err;
  EXPECT_EQ(std::count(measure.err.begin(), measure.err.end(), '\n'), 1) << measure.err;
}

// A shot whose corners a person put roughly (each 15 px off) comes back fitted: the far
// wall within 2 px of the truth, the shot's other fields kept, each corner's move said.
TEST_F(DetectCommand, HintFitsTheCornersOfARoughShot) {
  const auto cases = pw::metrology::detect::testing::loadCorridorCases({"corridor_f"});
  const auto& c = cases[0];
  const fs::path rough = dir_ / "rough.json", fitted = dir_ / "fitted.json";
  nlohmann::json doc = {{"image", c.imagePath}, {"focal_px", c.focalPx},
                        {"principal_point", {c.principalPoint.x, c.principalPoint.y}},
                        {"camera_height_m", c.cameraHeightM}, {"note", "mine"}};
  const double offsets[8][2] = {{15, 0}, {0, -15}, {-11, 10}, {10.6, 10.6}, {-15, 0}, {0, 15}, {12, -9}, {-9, -12}};
  for (int k = 0; k < 8; ++k) {
    doc["corners_px"]["P" + std::to_string(k + 1)] = {c.corners[k].x + offsets[k][0], c.corners[k].y + offsets[k][1]};
  }
  std::ofstream(rough) << doc.dump();
  const CommandRun r = run("detect --hint " + rough.string() + " -o " + fitted.string());
  ASSERT_TRUE(r.exitCode == 0 || r.exitCode == 3) << r.err;
  EXPECT_NE(r.out.find("moved"), std::string::npos) << r.out;
  const nlohmann::json out = nlohmann::json::parse(slurp(fitted));
  EXPECT_EQ(out["note"], "mine");
  EXPECT_DOUBLE_EQ(out["camera_height_m"].get<double>(), c.cameraHeightM);
  for (int k = 0; k < 4; ++k) {
    const auto& p = out["corners_px"]["P" + std::to_string(k + 1)];
    EXPECT_LT(glm::length(glm::dvec2(p[0].get<double>(), p[1].get<double>()) - c.corners[k]), 2.0) << "P" << k + 1;
  }
  const CommandRun measure = run("measure " + fitted.string());
  EXPECT_EQ(measure.exitCode, 0) << measure.err;
}

TEST_F(DetectCommand, BadInputIsExitOneWithOneLine) {
  const fs::path shot = dir_ / "shot.json";
  for (const std::string& args : {"detect " + (dir_ / "missing.png").string() + " -o " + shot.string(),
                                  "detect " + (dir_ / "missing.png").string(),
                                  "detect x.png -o " + shot.string() + " --focal-px abc",
                                  "detect x.png -o " + shot.string() + " --principal-point 3",
                                  "detect x.png -o " + shot.string() + " --camera-height -1",
                                  "detect x.png -o " + shot.string() + " --frobnicate",
                                  "detect --hint " + (dir_ / "missing.json").string() + " -o " + shot.string(),
                                  "detect --hint x.json -o " + shot.string() + " --hint-reach 0"}) {
    const CommandRun r = run(args);
    EXPECT_EQ(r.exitCode, 1) << args;
    EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
  }
  const fs::path notImage = dir_ / "not_an_image.png";
  std::ofstream(notImage) << "hello";
  const CommandRun r = run("detect " + notImage.string() + " -o " + shot.string());
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("not a readable"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(shot));
}

}  // namespace
