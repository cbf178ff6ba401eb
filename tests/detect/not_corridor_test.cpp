// Photos that are not corridors must give "no corridor found", never made-up corners.
#include <random>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "metrology/detect/detect.h"

namespace pw::metrology::detect {
namespace {

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

// Sky, a horizon, grass, trees (trunks and crowns), a house with a roof, noise.
cv::Mat drawOutdoorScene(unsigned seed) {
  cv::Mat o(600, 800, CV_8UC3);
  for (int y = 0; y < 600; ++y)
    for (int x = 0; x < 800; ++x)
      o.at<cv::Vec3b>(y, x) = y < 260 ? cv::Vec3b(230 - y / 4, 190 - y / 6, 140 - y / 8) : cv::Vec3b(60, 120 + (y - 260) / 8, 70);
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> xs(0, 800), sizes(20, 60);
  for (int i = 0; i < 9; ++i) {
    const int x = xs(rng), s = sizes(rng), base = 260 + 2 * s;
    cv::rectangle(o, cv::Rect(x - s / 6, base - 3 * s, s / 3, 3 * s), cv::Scalar(30, 60, 90), cv::FILLED);
    cv::circle(o, {x, base - 3 * s}, s, cv::Scalar(40, 110 + s, 50), cv::FILLED);
  }
  cv::rectangle(o, cv::Rect(520, 180, 160, 110), cv::Scalar(90, 110, 180), cv::FILLED);
  const std::vector<cv::Point> roof = {{510, 180}, {600, 120}, {690, 180}};
  cv::fillConvexPoly(o, roof, cv::Scalar(40, 40, 120));
  cv::Mat noise(o.size(), CV_8UC3);
  cv::randn(noise, 0, 12);
  cv::add(o, noise, o);
  return o;
}

// The hardest outdoor case for a corridor detector: a straight road whose edges and
// centre line converge to a vanishing point on the horizon, with verges and sky.
cv::Mat drawRoadScene() {
  cv::Mat o = drawOutdoorScene(11);
  const cv::Point vp(400, 260);
  const std::vector<cv::Point> road = {vp, {40, 599}, {760, 599}};
  cv::fillConvexPoly(o, road, cv::Scalar(70, 70, 75), cv::LINE_AA);
  cv::line(o, vp, {400, 599}, cv::Scalar(240, 240, 240), 3, cv::LINE_AA);
  cv::line(o, vp, {120, 599}, cv::Scalar(220, 220, 220), 2, cv::LINE_AA);
  cv::line(o, vp, {680, 599}, cv::Scalar(220, 220, 220), 2, cv::LINE_AA);
  return o;
}

TEST(DetectNotCorridor, BlankImage) { expectNoCorridor(cv::Mat(600, 800, CV_8UC3, cv::Scalar(128, 128, 128)), "blank grey"); }

TEST(DetectNotCorridor, Noise) {
  cv::Mat noise(600, 800, CV_8UC3);
  cv::randu(noise, 0, 256);
  expectNoCorridor(noise, "uniform noise");
}

TEST(DetectNotCorridor, SyntheticOutdoorScene) { expectNoCorridor(drawOutdoorScene(7), "drawn outdoor scene"); }

TEST(DetectNotCorridor, SyntheticRoadWithVanishingPoint) { expectNoCorridor(drawRoadScene(), "drawn road to the horizon"); }

TEST(DetectNotCorridor, RealOutdoorPhotos) {
  for (const char* name : {"camera.png", "rocket.jpg"}) {
    const cv::Mat photo = cv::imread(std::string(PW_TEST_DATA_DIR) + "/detect/" + name, cv::IMREAD_COLOR);
    ASSERT_FALSE(photo.empty()) << name;
    expectNoCorridor(photo, name);
  }
}

}  // namespace
}  // namespace pw::metrology::detect
