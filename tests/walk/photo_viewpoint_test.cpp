// The "Photo" viewpoint in `photowalk walk` shows what `photowalk render --camera-from`
// shows: the model's first viewpoint carries the photo's exact intrinsics (focal
// length and principal point, README "What a model file carries beyond VRML97"), and
// the walk uses them there. Checked on the ground truth's corridor_h (principal point
// 30 px right of and 23.5 px above the centre, rolled 6 degrees) and on corridor_a cropped so that its
// principal point lies 40 px off the image centre, through the .wrl and the .glb.
// Runs under xvfb-run on lavapipe with validation on (walk and render exit non-zero on
// any validation message).

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "tests/support/groundtruth.h"
#include "tests/walk/walk_run.h"

namespace pw::walk {
namespace {
namespace fs = std::filesystem;

using test::CommandRun;

double psnr(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat diff;
  cv::absdiff(a, b, diff);
  diff.convertTo(diff, CV_64F);
  const cv::Scalar mse = cv::mean(diff.mul(diff));
  const double m = (mse[0] + mse[1] + mse[2]) / 3.0;
  return m > 0 ? 10.0 * std::log10(255.0 * 255.0 / m) : 99.0;
}

class PhotoViewpoint : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no X display (run under xvfb-run)";
    setenv("PW_VALIDATION", "1", 1);
    dir_ = fs::path(PW_BINARY_DIR) / "test-output" / "photo_viewpoint";
    fs::create_directories(dir_);
  }

  // Builds `shot` into NAME.wrl and NAME.glb, renders it with --camera-from and
  // captures the walk's first frame at viewpoint 1 at the photo's size; returns the
  // PSNR between the two frames for each model file (wrl, glb).
  std::pair<double, double> walkAgainstRender(const std::string& name, const fs::path& shot, int width, int height) {
    const fs::path wrl = dir_ / (name + ".wrl"), glb = dir_ / (name + ".glb");
    const CommandRun built = photowalk("build " + shot.string() + " -o " + wrl.string() + " --gltf " + glb.string());
    EXPECT_EQ(built.exitCode, 0) << built.output;
    const fs::path rendered = dir_ / (name + "_render.png");
    const CommandRun render = photowalk("render " + wrl.string() + " --camera-from " + shot.string() + " -o " +
                                        rendered.string());
    EXPECT_EQ(render.exitCode, 0) << render.output;
    const cv::Mat expected = cv::imread(rendered.string());
    EXPECT_EQ(expected.cols, width);
    EXPECT_EQ(expected.rows, height);
    double result[2] = {0, 0};
    int i = 0;
    for (const fs::path& model : {wrl, glb}) {
      const std::string label = name + "_" + model.extension().string().substr(1);
      const fs::path capture = dir_ / (label + "_walk.png"), script = dir_ / (label + ".replay");
      // Nothing pressed: the walk stays at viewpoint 1 where it starts.
      std::ofstream(script) << "3 capture " << capture.filename().string() << "\n4 quit\n";
      const CommandRun walked = photowalk("walk " + model.string() + " --size " + std::to_string(width) + "x" +
                                          std::to_string(height) + " --no-vsync --replay " + script.string());
      EXPECT_EQ(walked.exitCode, 0) << walked.output;
      const cv::Mat actual = cv::imread(capture.string());
      if (actual.size() != expected.size() || expected.empty()) {
        ADD_FAILURE() << label << ": capture " << actual.cols << "x" << actual.rows << ", render " << expected.cols
                      << "x" << expected.rows;
        continue;
      }
      result[i++] = psnr(actual, expected);
      std::printf("[photo viewpoint] %s: walk vs render --camera-from %.2f dB\n", label.c_str(), result[i - 1]);
    }
    return {result[0], result[1]};
  }

  fs::path dir_;
};

// The issue asks 35 dB or better; the tests hold each figure at its measured value less
// 3 dB (the walk draws with 1x MSAA and trilinear filtering on lavapipe, render with
// 4x and anisotropic). A walk without the photo's principal point or roll falls to
// 15-22 dB.
constexpr double kMarginDb = 3.0;

// corridor_h: 1024 x 768, principal point (541.5, 360), roll -6 degrees.
// Measured: 55.2 dB (.wrl and .glb); 22.2 dB before the viewpoint carried the
// intrinsics and the walk kept the viewpoint's roll there.
TEST_F(PhotoViewpoint, WalkAtThePhotoViewpointShowsWhatRenderCameraFromShows) {
  const groundtruth::GroundTruth truth = groundtruth::loadGroundTruth("corridor_h");
  const auto [wrl, glb] = walkAgainstRender("corridor_h", truth.shot, truth.imageWidth, truth.imageHeight);
  EXPECT_GE(wrl, 55.2 - kMarginDb);
  EXPECT_GE(glb, 55.2 - kMarginDb);
  EXPECT_NEAR(wrl, glb, 1.0);
}

// corridor_a (principal point at the centre) without its leftmost 80 columns: the
// principal point lies 40 px left of the new image's centre (720 x 600).
// Measured: 52.1 dB; 15.5 dB before.
TEST_F(PhotoViewpoint, ACroppedPhotosViewpointKeepsItsPrincipalPoint) {
  const groundtruth::GroundTruth truth = groundtruth::loadGroundTruth("corridor_a");
  constexpr int kCropPx = 80;
  const cv::Mat photo = cv::imread(truth.image.string());
  ASSERT_FALSE(photo.empty());
  const cv::Mat cropped = photo.colRange(kCropPx, photo.cols).clone();
  ASSERT_TRUE(cv::imwrite((dir_ / "cropped.png").string(), cropped));
  nlohmann::json shot;
  shot["image"] = "cropped.png";
  shot["focal_px"] = truth.focalPx;
  const glm::dvec2 principal = truth.principalPointPx - glm::dvec2(kCropPx, 0);
  ASSERT_NEAR(principal.x - (cropped.cols - 1) * 0.5, -40.0, 1e-9);
  shot["principal_point"] = {principal.x, principal.y};
  shot["camera_height_m"] = truth.cameraHeightM;
  for (int k = 0; k < 8; ++k) {
    shot["corners_px"]["P" + std::to_string(k + 1)] = {truth.cornersPx[k].x - kCropPx, truth.cornersPx[k].y};
  }
  std::ofstream(dir_ / "cropped.json") << shot.dump(1);
  const auto [wrl, glb] = walkAgainstRender("cropped", dir_ / "cropped.json", cropped.cols, cropped.rows);
  EXPECT_GE(wrl, 52.1 - kMarginDb);
  EXPECT_GE(glb, 52.1 - kMarginDb);
  EXPECT_NEAR(wrl, glb, 1.0);
}

}  // namespace
}  // namespace pw::walk
