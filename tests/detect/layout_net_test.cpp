// The layout network (metrology/detect/layout_net.h) on corridors it was not trained on:
// the synthetic ray-cast corridors of these tests (trained on the random POV-Ray scenes
// only), and its box's corners.
#include <cmath>

#include <gtest/gtest.h>

#include "metrology/detect/detect.h"
#include "metrology/detect/layout_net.h"
#include "tests/detect/synthetic_corridor.h"

namespace pw::metrology::detect {
namespace {

using testing::CorridorSpec;
using testing::renderCorridor;

struct Looked {
  std::optional<LayoutFit> fit;
  std::optional<std::array<glm::dvec2, 8>> corners;
  CorridorAxes axes;
};

Looked look(const testing::SyntheticCorridor& scene, double focalPx) {
  DetectOptions options;
  options.focalPx = focalPx;
  options.principalPointPx = scene.principalPoint;
  auto d = detectCorridor(scene.image, options);
  EXPECT_TRUE(d.ok() && d->hasVanishingPoints);
  if (!d.ok() || !d->hasVanishingPoints) return {};
  const CorridorAxes axes = corridorAxes(d->horizontal.point, d->vertical.point, d->corridor.point, focalPx, scene.principalPoint);
  Looked out;
  out.axes = axes;
  out.fit = fitLayout(scene.image, 1.0, focalPx, scene.principalPoint, axes);
  if (out.fit) out.corners = layoutCorners(*out.fit, focalPx, scene.principalPoint, axes, scene.image.size(), 6.0);
  return out;
}

double worstFarError(const std::array<glm::dvec2, 8>& corners, const testing::SyntheticCorridor& scene) {
  double worst = 0;
  for (int k = 0; k < 4; ++k) worst = std::max(worst, glm::length(corners[k] - scene.farWall[k]));
  return worst;
}

// What the network is not: these corridors' far walls (a green wall with a brown door,
// 140 x 160 px) are unlike any of the random scenes', and it takes the door for the far
// wall (measured 2026-12-06: worst far corner 54.7, 79.1 and 32.1 px off). Detection
// finds these by their edges, sure, and never asks the network; where it does ask, the
// network's box counts only where the photo's edges bear it out (detect.cpp,
// findCorridor). Held at the measured figures, so that a network that does worse fails.
TEST(LayoutNet, CorridorsFromAnotherRendererAreWithinTheMeasuredError) {
  for (auto [yaw, pitch, roll, x, limit] : {std::array{0.0, 0.0, 0.0, 0.0, 60.0}, std::array{5.0, -4.0, 2.0, 0.3, 87.0},
                                           std::array{-8.0, 5.0, -4.0, 0.5, 36.0}}) {
    CorridorSpec spec;
    spec.yawDeg = yaw, spec.pitchDeg = pitch, spec.rollDeg = roll, spec.cameraXM = x;
    const auto scene = renderCorridor(spec);
    const Looked looked = look(scene, spec.focalPx);
    ASSERT_TRUE(looked.fit && looked.corners) << "yaw " << yaw;
    EXPECT_LT(looked.fit->left, looked.fit->right);
    EXPECT_LT(looked.fit->bottom, looked.fit->top);
    EXPECT_LE(looked.fit->score, 0.0);
    EXPECT_LT(worstFarError(*looked.corners, scene), limit) << "yaw " << yaw;
  }
}

TEST(LayoutNet, NearCornersLieOnTheRaysThroughTheFarOnesInsideThePhoto) {
  CorridorSpec spec;
  spec.yawDeg = 6, spec.pitchDeg = 3, spec.rollDeg = -2, spec.cameraXM = -0.4;
  const auto scene = renderCorridor(spec);
  const Looked looked = look(scene, spec.focalPx);
  ASSERT_TRUE(looked.corners);
  const auto& c = *looked.corners;
  // P5..P8 on the lines from the corridor's vanishing point through P3, P4, P1, P2.
  for (auto [far, near] : {std::pair{2, 4}, std::pair{3, 5}, std::pair{0, 6}, std::pair{1, 7}}) {
    const glm::dvec2 a = c[far] - scene.vanishingPoint, b = c[near] - scene.vanishingPoint;
    EXPECT_LT(std::abs(a.x * b.y - a.y * b.x) / glm::length(b), 0.5) << "P" << near + 1;
    EXPECT_GT(glm::length(b), glm::length(a)) << "P" << near + 1;
    EXPECT_GE(c[near].x, 6.0 - 1e-6);
    EXPECT_GE(c[near].y, 6.0 - 1e-6);
    EXPECT_LE(c[near].x, scene.image.cols - 7.0 + 1e-6);
    EXPECT_LE(c[near].y, scene.image.rows - 7.0 + 1e-6);
  }
  // The nearest such section: one of them touches the margin.
  double closest = 1e9;
  for (int k = 4; k < 8; ++k) {
    closest = std::min({closest, c[k].x - 6.0, c[k].y - 6.0, scene.image.cols - 7.0 - c[k].x, scene.image.rows - 7.0 - c[k].y});
  }
  EXPECT_LT(closest, 0.01);
}

// boxScore, which weighs an answer of the edges against the network's own box: the
// network's box scores what its fit scored, and a box moved off it scores less. (In the
// far wall's neighbourhood, where the box was fitted; in the whole photo, a box moved
// well aside: these scenes' far wall is larger than the door the network takes for it,
// so a larger box is no test there.)
TEST(LayoutNet, ABoxMovedOffTheNetworksOwnScoresLess) {
  CorridorSpec spec;
  spec.yawDeg = 4, spec.pitchDeg = -2;
  const auto scene = renderCorridor(spec);
  const Looked looked = look(scene, spec.focalPx);
  ASSERT_TRUE(looked.fit && looked.corners);
  const auto& c = *looked.corners;
  const std::array<glm::dvec2, 4> own = {c[0], c[1], c[2], c[3]};
  const auto score = [&](const std::array<glm::dvec2, 4>& far, bool zoomed) {
    return boxScore(*looked.fit, far, spec.focalPx, scene.principalPoint, looked.axes, zoomed);
  };
  const auto ownNear = score(own, true), ownWhole = score(own, false);
  ASSERT_TRUE(ownNear && ownWhole);
  // (Not to the last digit: the corners are cast through the three vanishing directions
  // as found, which are not exactly orthogonal, and read back by the network's own
  // coordinates, the rays' components along them.)
  EXPECT_NEAR(*ownNear, looked.fit->score, 0.01);
  EXPECT_LE(*ownWhole, 0.0);
  const glm::dvec2 middle = 0.25 * (c[0] + c[1] + c[2] + c[3]);
  for (const double times : {0.7, 1.4}) {
    std::array<glm::dvec2, 4> scaled{};
    for (int k = 0; k < 4; ++k) scaled[k] = middle + times * (own[k] - middle);
    const auto moved = score(scaled, true);
    ASSERT_TRUE(moved);
    EXPECT_LT(*moved, *ownNear - 0.05) << times << " times as large";
  }
  std::array<glm::dvec2, 4> aside{};
  for (int k = 0; k < 4; ++k) aside[k] = own[k] + glm::dvec2(0.25 * scene.image.cols, 0);
  const auto movedWhole = score(aside, false);
  ASSERT_TRUE(movedWhole);
  EXPECT_LT(*movedWhole, *ownWhole - 0.05);
  // A fit that did not look (made up, not fitLayout's) scores nothing.
  EXPECT_FALSE(boxScore(LayoutFit{}, own, spec.focalPx, scene.principalPoint, looked.axes, true));
}

TEST(LayoutNet, APlainGreyPhotoGivesNoNumbersThatAreNotNumbers) {
  const cv::Mat grey(480, 640, CV_8UC3, cv::Scalar(128, 128, 128));
  const CorridorAxes straight{{1, 0, 0}, {0, -1, 0}, {0, 0, 1}};
  const auto fit = fitLayout(grey, 1.0, 500.0, {319.5, 239.5}, straight);
  if (fit) {
    for (double v : {fit->left, fit->right, fit->bottom, fit->top, fit->score}) EXPECT_TRUE(std::isfinite(v));
  }
  EXPECT_FALSE(fitLayout(cv::Mat(), 1.0, 500.0, {319.5, 239.5}, straight));
}

}  // namespace
}  // namespace pw::metrology::detect
