// Photos that are not corridors must give "no corridor found", never made-up corners.
#include <random>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "metrology/detect/detect.h"
#include "metrology/shot.h"
#include "tests/detect/synthetic_corridor.h"

namespace pw::metrology::detect {
namespace {

using testing::drawOutdoorScene;
using testing::drawRoadScene;
using testing::kRoadVanishingPoint;

void expectNoCorridor(const cv::Mat& photo, const char* what) {
  auto d = detectCorridor(photo, DetectOptions{.focalPx = 700.0});
  ASSERT_TRUE(d.ok()) << what << ": " << d.message();
  EXPECT_FALSE(d->found) << what << ": corners were made up";
  EXPECT_FALSE(d->notFoundReason.empty()) << what;
  std::printf("%-28s no corridor: %s\n", what, d->notFoundReason.c_str());
  // Without a focal length too.
  auto withoutFocal = detectCorridor(photo, DetectOptions{});
  ASSERT_TRUE(withoutFocal.ok()) << what;
  EXPECT_FALSE(withoutFocal->found) << what << " (focal withheld)";
}

TEST(DetectNotCorridor, BlankImage) { expectNoCorridor(cv::Mat(600, 800, CV_8UC3, cv::Scalar(128, 128, 128)), "blank grey"); }

TEST(DetectNotCorridor, Noise) {
  cv::Mat noise(600, 800, CV_8UC3);
  cv::randu(noise, 0, 256);
  expectNoCorridor(noise, "uniform noise");
}

TEST(DetectNotCorridor, SyntheticOutdoorScene) { expectNoCorridor(drawOutdoorScene(7), "drawn outdoor scene"); }

TEST(DetectNotCorridor, SyntheticRoadWithVanishingPoint) { expectNoCorridor(drawRoadScene(), "drawn road to the horizon"); }

// No box, but the road's vanishing point, the trunks' vertical and the horizon are
// found and kept; the editor's starting box recedes to the road's point.
TEST(DetectNotCorridor, TheVanishingPointsFoundAreKeptWithoutABox) {
  DetectOptions options;
  options.focalPx = 700;
  auto d = detectCorridor(drawRoadScene(), options);
  ASSERT_TRUE(d.ok());
  ASSERT_FALSE(d->found);
  ASSERT_TRUE(d->hasVanishingPoints) << d->notFoundReason;
  ASSERT_TRUE(d->corridor.isFinite());
  EXPECT_LT(glm::length(d->corridor.pixel() - glm::dvec2(kRoadVanishingPoint.x, kRoadVanishingPoint.y)), 3.0);
  auto box = boxAlongVanishingPoints(*d, cv::Size(800, 600));
  ASSERT_TRUE(box);
  // Each receding edge of the box runs through the corridor's vanishing point.
  for (auto [far, near] : {std::pair{P1, P7}, {P2, P8}, {P3, P5}, {P4, P6}}) {
    const glm::dvec2 a = (*box)[far] - d->corridor.pixel(), b = (*box)[near] - d->corridor.pixel();
    EXPECT_LT(std::abs(a.x * b.y - a.y * b.x) / glm::length(b), 1e-6 * glm::length(a) + 1e-6) << far;
    EXPECT_GT(glm::length(b), glm::length(a)) << far;
  }
  for (const glm::dvec2& p : *box) EXPECT_TRUE(p.x >= 0 && p.y >= 0 && p.x <= 799 && p.y <= 599);
}

TEST(DetectNotCorridor, RealOutdoorPhotos) {
  for (const char* name : {"camera.png", "rocket.jpg"}) {
    const cv::Mat photo = cv::imread(std::string(PW_TEST_DATA_DIR) + "/detect/" + name, cv::IMREAD_COLOR);
    ASSERT_FALSE(photo.empty()) << name;
    expectNoCorridor(photo, name);
  }
}

}  // namespace
}  // namespace pw::metrology::detect
