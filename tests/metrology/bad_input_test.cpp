// Degenerate and wrong shots give one-line errors naming the problem, never a crash
// or a NaN.
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "metrology/measure.h"
#include "metrology/seed_method.h"
#include "metrology/shot_check.h"
#include "tests/metrology/synthetic_corridor.h"

namespace pw::metrology {
namespace {

using testing::SyntheticCorridor;

// Both methods must fail with a message containing `needle`, on one line.
void expectError(const Shot& shot, const std::string& needle) {
  for (Method method : {Method::kGeneral, Method::kSeed}) {
    MeasureOptions options;
    options.method = method;
    auto m = measureCorridor(shot, options);
    ASSERT_FALSE(m.ok()) << methodName(method) << " accepted a bad shot; width " << m->size.widthM;
    EXPECT_NE(m.message().find(needle), std::string::npos) << methodName(method) << ": " << m.message();
    EXPECT_EQ(m.message().find('\n'), std::string::npos) << m.message();
  }
}

Shot good() { return SyntheticCorridor{}.shot(); }

TEST(BadInput, GoodShotPasses) { EXPECT_TRUE(checkShot(good()).ok()); }

TEST(BadInput, NonPositiveOrNonFiniteCamera) {
  Shot s = good();
  s.focalPx = 0;
  expectError(s, "focal length");
  s.focalPx = -5;
  expectError(s, "focal length");
  s.focalPx = std::numeric_limits<double>::quiet_NaN();
  expectError(s, "focal length");
  s = good();
  s.cameraHeightM = 0.0;
  expectError(s, "camera_height_m");
  s.cameraHeightM = std::numeric_limits<double>::infinity();
  expectError(s, "camera_height_m");
  s = good();
  s.cameraHeightM.reset();
  expectError(s, "scale is unknown");
  s.reference = ReferenceLength{P3, P3, 2.0};
  expectError(s, "two different corners");
  s.reference = ReferenceLength{P3, P4, -1.0};
  expectError(s, "length_m");
  s = good();
  s.principalPointPx = glm::dvec2(std::nan(""), 3);
  expectError(s, "principal point");
  s = good();
  s.imageWidth = 0;
  expectError(s, "zero size");
}

TEST(BadInput, NonFiniteOrFarOutsideCorner) {
  Shot s = good();
  s.cornersPx[P4].x = std::numeric_limits<double>::quiet_NaN();
  expectError(s, "corner P4 is not a finite number");
  s = good();
  s.cornersPx[P6] = glm::dvec2(3000, 200);
  expectError(s, "corner P6 lies more than the image's size outside");
}

TEST(BadInput, CrossedQuadsFromSwappedCorners) {
  Shot s = good();
  std::swap(s.cornersPx[P1], s.cornersPx[P2]);
  expectError(s, "far wall quad P1-P2-P4-P3 crosses itself");
  s = good();
  std::swap(s.cornersPx[P5], s.cornersPx[P6]);
  expectError(s, "crosses itself");
  s = good();
  // Left and right swapped throughout: every quad runs the wrong way round.
  for (auto [a, b] : {std::pair{P1, P2}, {P3, P4}, {P5, P6}, {P7, P8}}) std::swap(s.cornersPx[a], s.cornersPx[b]);
  expectError(s, "left and right corners are swapped");
  s = good();
  for (auto [a, b] : {std::pair{P1, P3}, {P2, P4}, {P7, P5}, {P8, P6}}) std::swap(s.cornersPx[a], s.cornersPx[b]);
  expectError(s, "top and bottom corners are swapped");
}

TEST(BadInput, CollinearAndCoincidentCorners) {
  Shot s = good();
  // P2 moved onto the line P3-P1 (above P1): the far wall has P3, P1, P2 on one line.
  s.cornersPx[P2] = s.cornersPx[P1] + 0.5 * (s.cornersPx[P1] - s.cornersPx[P3]);
  expectError(s, "corners P3, P1 and P2 are collinear; the far wall plane is degenerate");
  s = good();
  s.cornersPx[P2] = s.cornersPx[P1] + glm::dvec2(0.2, 0);
  expectError(s, "corners P1 and P2 coincide");
}

TEST(BadInput, VanishingPointBehindTheCamera) {
  // Far and near corners exchanged: the receding edges converge towards the viewer.
  Shot s = good();
  for (auto [a, b] : {std::pair{P1, P7}, {P2, P8}, {P3, P5}, {P4, P6}}) std::swap(s.cornersPx[a], s.cornersPx[b]);
  auto m = measureCorridor(s);
  ASSERT_FALSE(m.ok());
  EXPECT_NE(m.message().find("far and near corners are swapped"), std::string::npos) << m.message();
  // The vanishing geometry itself, on corners that pass the quad checks: receding
  // edges converging on the near side.
  std::array<glm::dvec2, kCornerCount> c{};
  c[P1] = {100, 100}, c[P2] = {700, 100}, c[P3] = {100, 500}, c[P4] = {700, 500};
  c[P7] = {300, 250}, c[P8] = {500, 250}, c[P5] = {300, 350}, c[P6] = {500, 350};
  auto v = corridorVanishing(c);
  ASSERT_FALSE(v.ok());
  EXPECT_NE(v.message().find("behind the camera"), std::string::npos) << v.message();
}

TEST(BadInput, ParallelRecedingEdgesHaveNoLength) {
  std::array<glm::dvec2, kCornerCount> c{};
  c[P1] = {300, 100}, c[P2] = {500, 100}, c[P3] = {300, 500}, c[P4] = {500, 500};
  c[P7] = {100, 100}, c[P8] = {700, 100}, c[P5] = {100, 500}, c[P6] = {700, 500};
  auto v = corridorVanishing(c);
  ASSERT_FALSE(v.ok());
  EXPECT_NE(v.message().find("at infinity"), std::string::npos) << v.message();
}

TEST(BadInput, FloorCornerAboveTheHorizon) {
  // A camera held above the ceiling's height sees the ceiling from above: the
  // quads then run the wrong way or the floor leaves the horizon.
  SyntheticCorridor c;
  c.cameraHeightM = 3.5;
  Shot s = c.shot();
  s.cameraHeightM = 1.5;
  auto m = measureCorridor(s);
  EXPECT_FALSE(m.ok());
  // Direct: the seed construction refuses a floor corner above VP.
  std::array<glm::dvec2, kCornerCount> k = SyntheticCorridor{}.cornersPx();
  auto seed = seedConstruct(k, 692.82, 1.5);
  ASSERT_TRUE(seed.ok()) << seed.message();
  for (int i : {P3, P4, P5, P6}) k[i].y = 2 * 299.5 - k[i].y;  // mirror the floor above the horizon
  seed = seedConstruct(k, 692.82, 1.5);
  ASSERT_FALSE(seed.ok());
}

TEST(BadInput, NegativeSigmaIsRefused) {
  MeasureOptions o;
  o.cornerSigmaPx = -1;
  auto m = measureCorridor(good(), o);
  ASSERT_FALSE(m.ok());
  EXPECT_NE(m.message().find("standard deviation"), std::string::npos);
}

TEST(BadInput, RandomCornersNeverGiveNaN) {
  // Whatever the corners, a result is either an error or entirely finite and positive.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-100, 900), v(-100, 700);
  int measured = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    Shot s = good();
    const int moved = trial % 3 + 1;
    for (int k = 0; k < moved; ++k) s.cornersPx[(trial * 5 + k * 3) % kCornerCount] = glm::dvec2(u(rng), v(rng));
    for (Method method : {Method::kGeneral, Method::kSeed}) {
      MeasureOptions options;
      options.method = method;
      auto m = measureCorridor(s, options);
      if (!m.ok()) {
        EXPECT_FALSE(m.message().empty());
        continue;
      }
      ++measured;
      EXPECT_TRUE(std::isfinite(m->size.widthM) && m->size.widthM > 0);
      EXPECT_TRUE(std::isfinite(m->size.lengthM) && m->size.lengthM > 0);
      EXPECT_TRUE(std::isfinite(m->sigma.lengthM) && std::isfinite(m->reprojectionRmsPx));
    }
  }
  EXPECT_GT(measured, 0);  // some perturbed shots are still corridors
}

}  // namespace
}  // namespace pw::metrology
