// `detect --hint` (issue 22 part 5): a box a person placed roughly, every corner 15 px
// from the truth in a random direction, comes back fitted to the photo's edges and
// vanishing points. Prints the table (ctest -V).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "metrology/detect/detect.h"
#include "metrology/shot.h"
#include "tests/detect/corridor_cases.h"
#include "tests/detect/synthetic_corridor.h"

namespace pw::metrology::detect {
namespace {

using testing::CorridorCase;
using testing::medianOf;

constexpr double kRoughPx = 15.0;

// Every corner moved kRoughPx in a direction drawn from `seed`.
std::array<glm::dvec2, 8> roughly(const std::array<glm::dvec2, 8>& corners, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> angle(0, 2 * 3.14159265358979);
  std::array<glm::dvec2, 8> out = corners;
  for (glm::dvec2& p : out) {
    const double a = angle(rng);
    p += kRoughPx * glm::dvec2(std::cos(a), std::sin(a));
  }
  return out;
}

struct HintError {
  double farMedianPx = 0, farMaxPx = 0;
  double nearAcrossMaxPx = 0;  // the near corners' distance from the true boundary line
  bool confident = false;
};

HintError fitRough(const CorridorCase& c, unsigned seed) {
  DetectOptions options;
  options.focalPx = c.focalPx;
  options.principalPointPx = c.principalPoint;
  options.hintPx = roughly(c.corners, seed);
  auto d = detectCorridor(c.image, options);
  EXPECT_TRUE(d && d->found) << c.name;
  HintError e;
  if (!d || !d->found) return e;
  std::vector<double> far;
  for (int k = 0; k < 4; ++k) far.push_back(glm::length(d->corners[k].px - c.corners[k]));
  e.farMedianPx = medianOf(far);
  e.farMaxPx = *std::max_element(far.begin(), far.end());
  // P5..P8 keep the depth the person gave them; across their boundary they are measured.
  constexpr std::array<int, 4> kFarOf = {P3, P4, P1, P2}, kNearOf = {P5, P6, P7, P8};
  for (int b = 0; b < 4; ++b) {
    const glm::dvec2 along = glm::normalize(c.corners[kNearOf[b]] - c.corners[kFarOf[b]]);
    const glm::dvec2 off = d->corners[kNearOf[b]].px - c.corners[kFarOf[b]];
    e.nearAcrossMaxPx = std::max(e.nearAcrossMaxPx, std::abs(off.x * along.y - off.y * along.x));
  }
  e.confident = d->confident;
  if (e.farMaxPx >= 2.0) {
    for (const std::string& why : d->doubts) std::printf("    %s: %s\n", c.name.c_str(), why.c_str());
  }
  return e;
}

// Measured 2026-12-03: far wall within 0.52 px at worst over 24 rough boxes, the near
// corners within 1.64 px of their boundary (corridor_h); the issue asks for 2 px.
TEST(DetectHint, RoughBoxesOfTheCleanCorridorsComeBackWithinTwoPixels) {
  std::printf("%-12s %10s %10s %12s %s\n", "scene", "far med", "far max", "near across", "confident");
  unsigned seed = 1;
  for (const CorridorCase& c : testing::loadCorridorCases()) {
    for (int trial = 0; trial < 3; ++trial, ++seed) {
      const HintError e = fitRough(c, seed);
      std::printf("%-12s %9.3f %9.3f %11.3f   %s\n", c.name.c_str(), e.farMedianPx, e.farMaxPx, e.nearAcrossMaxPx,
                  e.confident ? "yes" : "no");
      EXPECT_LT(e.farMaxPx, 2.0) << c.name << " trial " << trial;
      EXPECT_LT(e.nearAcrossMaxPx, 2.0) << c.name << " trial " << trial;
    }
  }
}

// Measured 2026-12-03: the far wall's median corner within 2 px in 8 of 9 (0.10-0.92 px;
// clutter_1 17 px: a section 17 px nearer, with edges on three sides, wins), the
// hidden feet of clutter_5 and clutter_8 found where the boundaries meet the sides.
TEST(DetectHint, RoughBoxesOfTheClutteredCorridors) {
  std::vector<std::string> names;
  for (int i = 1; i <= 9; ++i) names.push_back("clutter_" + std::to_string(i));
  std::printf("%-12s %10s %10s %12s %s\n", "scene", "far med", "far max", "near across", "confident");
  std::vector<double> medians;
  unsigned seed = 101;
  for (const CorridorCase& c : testing::loadCorridorCases(names)) {
    const HintError e = fitRough(c, seed++);
    medians.push_back(e.farMedianPx);
    std::printf("%-12s %9.3f %9.3f %11.3f   %s\n", c.name.c_str(), e.farMedianPx, e.farMaxPx, e.nearAcrossMaxPx,
                e.confident ? "yes" : "no");
  }
  int within = 0;
  for (double m : medians) within += m < 2.0;
  std::printf("cluttered: far-wall median within 2 px in %d of %zu\n", within, medians.size());
  EXPECT_GE(within, 8);
}

// The York Urban corridor P1040811 in a synthetic photo: the ceiling painted the walls'
// colour (a white ceiling meeting white walls: no boundary shows along it), a pipe down
// the right wall 7 px beside the far wall's corner, and a faint step across the far wall
// 16 px below its top (the lamp's light ending). The far wall's sides are fitted first
// (fitFarWallNear) and every one of 30 rough boxes comes back to the far wall within a
// pixel (the painted ceiling's edge is on whole pixels: 0.8 px above the true top).
// Fitted on the boundaries, as before, 9 of the 30 came back as they were put ("P8 would
// move 50 px") and 2 others 5-7.5 px off.
TEST(DetectHint, AFarWallWhoseCeilingEdgesDoNotShowIsFittedSideBySide) {
  testing::CorridorSpec spec;
  testing::SyntheticCorridor c = testing::renderCorridor(spec);
  const glm::dvec2 vp = c.vanishingPoint;
  const auto at = [](glm::dvec2 p) { return cv::Point(static_cast<int>(std::lround(p.x)), static_cast<int>(std::lround(p.y))); };
  const auto beyond = [&](int k) { return at(vp + 20.0 * (c.farWall[k] - vp)); };
  const std::vector<cv::Point> ceiling = {at(c.farWall[P1]), beyond(P1), beyond(P2), at(c.farWall[P2])};
  cv::fillConvexPoly(c.image, ceiling, cv::Scalar(190, 205, 215));
  const glm::dvec2 pipe(7, 0);
  cv::line(c.image, at(c.farWall[P2] + pipe), at(c.farWall[P4] + pipe), cv::Scalar(90, 90, 90), 2);
  const int bandEnd = static_cast<int>(std::lround(c.farWall[P1].y)) + 16;
  for (int y = bandEnd; y <= static_cast<int>(c.farWall[P3].y) + 1; ++y) {
    for (int x = static_cast<int>(c.farWall[P1].x) - 1; x <= static_cast<int>(c.farWall[P2].x) + 1; ++x) {
      cv::Vec3b& px = c.image.at<cv::Vec3b>(y, x);
      if (px[1] < px[0] + 15 || px[1] < px[2] + 5) continue;  // the far wall's green only (BGR)
      for (int k = 0; k < 3; ++k) px[k] = cv::saturate_cast<uchar>(px[k] - 18);
    }
  }
  // The near section (the camera looks straight down the corridor: a homothety about the
  // vanishing point), three times the far wall.
  std::array<glm::dvec2, 8> truth{};
  for (int k = 0; k < 4; ++k) truth[k] = c.farWall[k];
  constexpr std::array<int, 4> kNearOfFar = {P7, P8, P5, P6};
  for (int k = 0; k < 4; ++k) truth[kNearOfFar[k]] = vp + 3.0 * (c.farWall[k] - vp);
  for (unsigned seed = 1; seed <= 30; ++seed) {
    DetectOptions options;
    options.focalPx = spec.focalPx;
    options.principalPointPx = c.principalPoint;
    options.hintPx = roughly(truth, seed);
    auto d = detectCorridor(c.image, options);
    ASSERT_TRUE(d && d->found) << seed;
    for (int k = 0; k < 4; ++k) {
      EXPECT_LT(glm::length(d->corners[k].px - truth[k]), 1.0) << "seed " << seed << " P" << k + 1;
    }
  }
}

TEST(DetectHint, ABoxThePhotoDoesNotBearOutComesBackAsGivenAndUnsure) {
  const auto cases = testing::loadCorridorCases({"corridor_a"});
  const CorridorCase& c = cases[0];
  DetectOptions options;
  options.focalPx = c.focalPx;
  std::array<glm::dvec2, 8> hint{};
  // All eight corners in a small square at the top left: no receding lines to fit.
  for (int k = 0; k < 8; ++k) hint[k] = glm::dvec2(20 + 3 * (k % 2), 20 + 3 * (k / 2));
  options.hintPx = hint;
  auto d = detectCorridor(c.image, options);
  ASSERT_TRUE(d);
  ASSERT_TRUE(d->found);
  EXPECT_FALSE(d->confident);
  EXPECT_FALSE(d->doubts.empty());
  for (int k = 0; k < 8; ++k) {
    EXPECT_EQ(d->corners[k].px, hint[k]) << k;
    EXPECT_EQ(d->corners[k].confidence, 0.0) << k;
  }
}

TEST(DetectHint, AHintThatIsNotANumberIsAnError) {
  const auto cases = testing::loadCorridorCases({"corridor_a"});
  DetectOptions options;
  std::array<glm::dvec2, 8> hint = cases[0].corners;
  hint[P6].x = std::nan("");
  options.hintPx = hint;
  auto d = detectCorridor(cases[0].image, options);
  ASSERT_FALSE(d);
  EXPECT_NE(d.message().find("P6"), std::string::npos) << d.message();
}

}  // namespace
}  // namespace pw::metrology::detect
