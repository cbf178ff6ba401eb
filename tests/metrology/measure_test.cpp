// measureCorridor on synthetic cameras with known answers (general and seed).
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "metrology/input_sigma.h"
#include "metrology/measure.h"
#include "tests/metrology/synthetic_corridor.h"

namespace pw::metrology {
namespace {

using testing::SyntheticCorridor;

void expectRelative(double got, double want, double tolerance, const char* what) {
  EXPECT_NEAR(got / want, 1.0, tolerance) << what << ": got " << got << ", want " << want;
}

void expectRecovers(const SyntheticCorridor& c, const Measurement& m, double tolerance) {
  expectRelative(m.size.widthM, c.widthM, tolerance, "width");
  expectRelative(m.size.heightM, c.heightM, tolerance, "height");
  expectRelative(m.size.lengthM, c.lengthM, tolerance, "length");
  EXPECT_NEAR(m.pose.positionM.x, c.cameraXM, 1e-5 + tolerance * c.widthM);
  EXPECT_NEAR(m.pose.positionM.y, c.cameraHeightM, 1e-9);
  EXPECT_NEAR(m.pose.positionM.z, c.cameraZM, tolerance * c.lengthM);
}

TEST(Measure, OnePointPerspectiveIsExact) {
  SyntheticCorridor c;
  auto m = measureCorridor(c.shot());
  ASSERT_TRUE(m.ok()) << m.message();
  expectRecovers(c, *m, 1e-7);
  EXPECT_LT(m->reprojectionRmsPx, 1e-5);
  EXPECT_NEAR(m->vanishing.corridor.px.x, 399.5, 1e-6);
  EXPECT_NEAR(m->vanishing.corridor.px.y, 299.5, 1e-6);
  EXPECT_FALSE(m->vanishing.horizontal.finite);
  EXPECT_FALSE(m->vanishing.vertical.finite);
  EXPECT_NEAR(m->pose.yawDeg, 0, 1e-6);
  EXPECT_NEAR(m->pose.pitchDeg, 0, 1e-6);
  EXPECT_NEAR(m->pose.rollDeg, 0, 1e-6);
}

struct PoseCase {
  double yaw, pitch, roll, cameraX;
};

class MeasureRotated : public ::testing::TestWithParam<PoseCase> {};

TEST_P(MeasureRotated, RecoversBoxAndPose) {
  SyntheticCorridor c;
  c.widthM = 3.0;
  c.heightM = 3.2;
  c.lengthM = 14.5;
  c.cameraHeightM = 1.6;
  c.cameraZM = 6.0;
  c.focalPx = 800;
  c.cameraXM = GetParam().cameraX;
  c.yawDeg = GetParam().yaw;
  c.pitchDeg = GetParam().pitch;
  c.rollDeg = GetParam().roll;
  auto m = measureCorridor(c.shot());
  ASSERT_TRUE(m.ok()) << m.message();
  expectRecovers(c, *m, 1e-7);
  EXPECT_NEAR(m->pose.yawDeg, c.yawDeg, 1e-5);
  EXPECT_NEAR(m->pose.pitchDeg, c.pitchDeg, 1e-5);
  EXPECT_NEAR(m->pose.rollDeg, c.rollDeg, 1e-5);
  EXPECT_LT(m->reprojectionRmsPx, 1e-5);
  // The fitted corners reproject onto the clicked ones.
  const auto corners = c.cornersPx();
  for (int i = 0; i < kCornerCount; ++i) EXPECT_LT(glm::length(m->reprojectedPx[i] - corners[i]), 1e-4) << cornerName(i);
}

INSTANTIATE_TEST_SUITE_P(UpToTenDegrees, MeasureRotated,
                         ::testing::Values(PoseCase{10, 0, 0, 0}, PoseCase{-10, 0, 0, 0.4}, PoseCase{0, 10, 0, 0},
                                           PoseCase{0, -10, 0, -0.3}, PoseCase{0, 0, 10, 0}, PoseCase{0, 0, -10, 0.5},
                                           PoseCase{7, -5, 3, 0.6}, PoseCase{-9, 8, -10, -0.7},
                                           PoseCase{10, 10, 10, 0.2}));

TEST(Measure, SignsOfTheAnglesMeanWhatTheHeaderSays) {
  SyntheticCorridor c;
  c.yawDeg = 5;
  // Turning left puts the far end of the corridor right of the image centre.
  EXPECT_GT(c.cornersPx()[P3].x + c.cornersPx()[P4].x, 2 * 399.5);
  c.yawDeg = 0;
  c.pitchDeg = 5;
  // Looking up moves the vanishing point down.
  auto up = measureCorridor(c.shot());
  ASSERT_TRUE(up.ok()) << up.message();
  EXPECT_GT(up->vanishing.corridor.px.y, 299.5 + 10);
  c.pitchDeg = 0;
  c.rollDeg = 5;
  // Positive roll: the horizon falls to the right.
  const auto k = c.cornersPx();
  EXPECT_GT(k[P6].y, k[P5].y);
  auto rolled = measureCorridor(c.shot());
  ASSERT_TRUE(rolled.ok()) << rolled.message();
  EXPECT_NEAR(rolled->vanishing.rollDeg, 5, 1e-6);
}

TEST(Measure, SeedAgreesWithGeneralOnOnePointPerspective) {
  for (double roll : {0.0, 4.0, -8.0}) {
    SyntheticCorridor c;
    c.cameraXM = 0.35;
    c.rollDeg = roll;
    MeasureOptions seed;
    seed.method = Method::kSeed;
    auto general = measureCorridor(c.shot());
    auto paper = measureCorridor(c.shot(), seed);
    ASSERT_TRUE(general.ok()) << general.message();
    ASSERT_TRUE(paper.ok()) << paper.message();
    expectRecovers(c, *paper, 1e-7);
    EXPECT_NEAR(paper->size.widthM / general->size.widthM, 1.0, 1e-3);
    EXPECT_NEAR(paper->size.heightM / general->size.heightM, 1.0, 1e-3);
    EXPECT_NEAR(paper->size.lengthM / general->size.lengthM, 1.0, 1e-3);
    EXPECT_NEAR(paper->pose.rollDeg, roll, 1e-6);
    EXPECT_LT(paper->reprojectionRmsPx, 1e-5);
  }
}

TEST(Measure, SeedIsBiasedUnderYawWhereGeneralIsNot) {
  // The paper's construction assumes the optical axis runs along the corridor.
  SyntheticCorridor c;
  c.yawDeg = 8;
  MeasureOptions seed;
  seed.method = Method::kSeed;
  auto paper = measureCorridor(c.shot(), seed);
  ASSERT_TRUE(paper.ok()) << paper.message();
  EXPECT_GT(std::abs(paper->size.lengthM / c.lengthM - 1.0), 0.005);
  EXPECT_GT(paper->reprojectionRmsPx, 1.0);
}

TEST(Measure, ReferenceLengthFixesTheScaleWithoutCameraHeight) {
  SyntheticCorridor c;
  c.yawDeg = 4;
  c.pitchDeg = -3;
  Shot shot = c.shot();
  shot.cameraHeightM.reset();
  shot.reference = ReferenceLength{P3, P5, c.lengthM};
  for (Method method : {Method::kGeneral, Method::kSeed}) {
    if (method == Method::kSeed) {
      c.yawDeg = c.pitchDeg = 0;
      shot.cornersPx = c.cornersPx();
    }
    MeasureOptions options;
    options.method = method;
    auto m = measureCorridor(shot, options);
    ASSERT_TRUE(m.ok()) << m.message();
    expectRecovers(c, *m, 1e-6);
    EXPECT_NEAR(m->cameraHeightM, c.cameraHeightM, 1e-6);
    ASSERT_TRUE(m->reference.has_value());
    EXPECT_TRUE(m->reference->usedForScale);
    EXPECT_NEAR(m->reference->errorPercent, 0, 1e-6);
    // The reference is the length itself: exact; the others inherit its scale.
    EXPECT_LT(m->sigma.lengthM, 1e-9);
    EXPECT_GT(m->sigma.widthM, 0.001);
  }
}

TEST(Measure, ReferenceLengthIsCheckedWhenTheHeightIsGiven) {
  SyntheticCorridor c;
  Shot shot = c.shot();
  shot.reference = ReferenceLength{P3, P4, 2 * c.widthM};  // wrong by a factor of two
  auto m = measureCorridor(shot);
  ASSERT_TRUE(m.ok()) << m.message();
  expectRecovers(c, *m, 1e-7);
  ASSERT_TRUE(m->reference.has_value());
  EXPECT_FALSE(m->reference->usedForScale);
  EXPECT_NEAR(m->reference->measuredM, c.widthM, 1e-6);
  EXPECT_NEAR(m->reference->errorPercent, -50, 1e-4);
}

TEST(Measure, AScaleInCentimetresOrMillimetresIsSaidToBeImplausible) {
  SyntheticCorridor c;  // 2.4 m wide by default, camera 1.5 m up
  Shot shot = c.shot();
  auto right = measureCorridor(shot);
  ASSERT_TRUE(right.ok()) << right.message();
  EXPECT_FALSE(implausibleSize(shot, *right).has_value()) << *implausibleSize(shot, *right);
  // The camera height in centimetres: every length 100 times too long.
  shot.cameraHeightM = 100 * c.cameraHeightM;
  auto centimetres = measureCorridor(shot);
  ASSERT_TRUE(centimetres.ok()) << centimetres.message();
  EXPECT_NEAR(centimetres->size.widthM, 100 * c.widthM, 1e-6 * 100 * c.widthM);
  const auto said = implausibleSize(shot, *centimetres);
  ASSERT_TRUE(said.has_value());
  EXPECT_NE(said->find("the camera height (150 m)"), std::string::npos) << *said;
  EXPECT_NE(said->find("in metres (not centimetres or millimetres)"), std::string::npos) << *said;
  // The reference length in millimetres, no camera height.
  shot.cameraHeightM.reset();
  shot.reference = ReferenceLength{P3, P4, 1000 * c.widthM};
  auto millimetres = measureCorridor(shot);
  ASSERT_TRUE(millimetres.ok()) << millimetres.message();
  const auto byReference = implausibleSize(shot, *millimetres);
  ASSERT_TRUE(byReference.has_value());
  EXPECT_NE(byReference->find("the reference length P3-P4 (" + std::to_string(int(1000 * c.widthM)) + " m)"),
            std::string::npos)
      << *byReference;
}

TEST(Measure, FocalFromMillimetres) {
  SyntheticCorridor c;
  Shot shot = c.shot();
  shot.focalPx = 0;
  shot.focalMm = FocalLengthMm{c.focalPx / c.imageWidth * 36.0, 36.0};
  auto m = measureCorridor(shot);
  ASSERT_TRUE(m.ok()) << m.message();
  expectRecovers(c, *m, 1e-7);
}

// The first-order sigma must match the spread of answers when the corners really
// are that noisy (Monte Carlo, 400 trials; 15% allows for the sampling error of a
// standard deviation from 400 draws, about 3.5%, and second-order effects).
void checkSigmaAgainstMonteCarlo(const SyntheticCorridor& c, Method method) {
  const Shot clean = c.shot();
  MeasureOptions options;
  options.method = method;
  options.cornerSigmaPx = 1.0;
  auto predicted = measureCorridor(clean, options);
  ASSERT_TRUE(predicted.ok()) << predicted.message();
  std::mt19937 rng(42);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<double> w, h, l;
  for (int trial = 0; trial < 400; ++trial) {
    Shot noisy = clean;
    for (auto& p : noisy.cornersPx) p += glm::dvec2(noise(rng), noise(rng));
    auto m = measureCorridor(noisy, options);
    ASSERT_TRUE(m.ok()) << m.message();
    w.push_back(m->size.widthM);
    h.push_back(m->size.heightM);
    l.push_back(m->size.lengthM);
  }
  auto sd = [](const std::vector<double>& v) {
    double mean = 0, sum = 0;
    for (double x : v) mean += x / v.size();
    for (double x : v) sum += (x - mean) * (x - mean);
    return std::sqrt(sum / (v.size() - 1));
  };
  std::printf("%s: Monte Carlo / predicted sigma: width %.3f height %.3f length %.3f\n", methodName(method),
              sd(w) / predicted->sigma.widthM, sd(h) / predicted->sigma.heightM, sd(l) / predicted->sigma.lengthM);
  EXPECT_NEAR(sd(w) / predicted->sigma.widthM, 1.0, 0.15) << "width " << sd(w) << " vs " << predicted->sigma.widthM;
  EXPECT_NEAR(sd(h) / predicted->sigma.heightM, 1.0, 0.15) << "height " << sd(h) << " vs " << predicted->sigma.heightM;
  EXPECT_NEAR(sd(l) / predicted->sigma.lengthM, 1.0, 0.15) << "length " << sd(l) << " vs " << predicted->sigma.lengthM;
}

TEST(Measure, GeneralSigmaMatchesMonteCarlo) {
  SyntheticCorridor c;
  c.yawDeg = 6;
  c.pitchDeg = -4;
  c.rollDeg = 2;
  checkSigmaAgainstMonteCarlo(c, Method::kGeneral);
}

TEST(Measure, SeedSigmaMatchesMonteCarlo) { checkSigmaAgainstMonteCarlo(SyntheticCorridor{}, Method::kSeed); }

TEST(Measure, SigmaScalesWithCornerSigmaAndCameraHeightSigma) {
  SyntheticCorridor c;
  MeasureOptions one, two, height;
  two.cornerSigmaPx = 2.0;
  height.cornerSigmaPx = 0.0;
  height.cameraHeightSigmaM = 0.015;  // 1% of 1.5 m
  auto a = measureCorridor(c.shot(), one);
  auto b = measureCorridor(c.shot(), two);
  auto h = measureCorridor(c.shot(), height);
  ASSERT_TRUE(a.ok() && b.ok() && h.ok());
  EXPECT_NEAR(b->sigma.lengthM, 2 * a->sigma.lengthM, 1e-9);
  EXPECT_NEAR(h->sigma.widthM, 0.01 * c.widthM, 1e-6);
  EXPECT_NEAR(h->sigma.lengthM, 0.01 * c.lengthM, 1e-6);
  // Farther away is less certain: the length's sigma exceeds the width's.
  EXPECT_GT(a->sigma.lengthM, a->sigma.widthM);
}

TEST(MeasureSigma, EachInputsShareAddsInQuadrature) {
  SyntheticCorridor c;
  c.yawDeg = 8, c.pitchDeg = 4;
  MeasureOptions options;
  options.focalSigmaRelative = 0.3;
  options.focalSigmaName = "the assumed focal length";
  options.cameraHeightSigmaM = 0.28;
  options.principalPointSigmaPx = 4;
  options.distortionSigmaK1 = 0.01;
  auto m = measureCorridor(c.shot(), options);
  auto today = measureCorridor(c.shot());
  ASSERT_TRUE(m.ok() && today.ok());
  ASSERT_EQ(m->sigmaSources.size(), 5u);
  EXPECT_EQ(m->sigmaSources[0].key, "corners");
  for (int d = 0; d < 3; ++d) {
    double sum = 0;
    for (const SigmaSource& s : m->sigmaSources) sum += std::pow(dimensionOf(s.sigma, d), 2);
    EXPECT_NEAR(std::sqrt(sum), dimensionOf(m->sigma, d), 1e-12);
    // The corners' share is today's sigma; the measurement itself does not move.
    EXPECT_NEAR(dimensionOf(m->sigmaSources[0].sigma, d), dimensionOf(today->sigma, d), 1e-12);
    EXPECT_NEAR(dimensionOf(m->size, d), dimensionOf(today->size, d), 1e-12);
  }
  // The camera height: proportional (0.28 / 1.5 of each dimension).
  EXPECT_NEAR(m->sigmaSources[1].sigma.widthM, c.widthM * 0.28 / 1.5, 1e-6);
  // A 30% focal length dominates the length, which scales with it.
  const SigmaSource* top = dominantSigmaSource(*m, 2);
  ASSERT_NE(top, nullptr);
  EXPECT_EQ(top->key, "focal_length");
  EXPECT_GT(m->sigmaSources[2].sigma.lengthM, 0.15 * c.lengthM);
  EXPECT_NE(dimensionWithSource(*m, 2).find("(mostly: the assumed focal length)"), std::string::npos);
}

TEST(MeasureSigma, FocalLengthsWeighedByInverseVariance) {
  // Equal sigmas: the geometric mean, sigma / sqrt(2).
  WeighedFocal w = weighFocal(600, 0.03, 630, 0.03);
  EXPECT_TRUE(w.usedSecond);
  EXPECT_NEAR(w.focalPx, std::sqrt(600.0 * 630.0), 1e-9);
  EXPECT_NEAR(w.sigmaRelative, 0.03 / std::sqrt(2.0), 1e-12);
  // A second estimate four times as uncertain moves the first by a seventeenth.
  w = weighFocal(647, 0.03, 700, 0.12);
  EXPECT_NEAR(std::log(w.focalPx / 647), std::log(700.0 / 647) / 17, 1e-12);
  // Beyond 2 sigma of their difference: the first alone.
  w = weighFocal(647, 0.03, 500, 0.10);
  EXPECT_FALSE(w.usedSecond);
  EXPECT_EQ(w.focalPx, 647);
  EXPECT_EQ(w.sigmaRelative, 0.03);
}

TEST(MeasureSigma, DigitsFollowTheSigma) {
  EXPECT_EQ(dimensionText(2.5634, 0.3, "+/-"), "2.6 m +/- 0.3");
  EXPECT_EQ(dimensionText(2.5634, 0.015, "+/-"), "2.563 m +/- 0.015");
  EXPECT_EQ(dimensionText(2.5634, 0.04, "+/-"), "2.56 m +/- 0.04");
  EXPECT_EQ(dimensionText(12.34, 1.2, "+/-"), "12.3 m +/- 1.2");
  EXPECT_EQ(dimensionText(12.34, 4.0, "+/-"), "12 m +/- 4");
  EXPECT_EQ(dimensionText(2.5634, 0.0001, "+/-"), "2.563 m +/- 0.000");
  EXPECT_EQ(dimensionText(2.5634, 0.3), "2.6 m \u00b1 0.3");
}

TEST(Measure, HorizonOfTheFittedCameraPassesThroughTheVanishingPoint) {
  SyntheticCorridor c;
  c.yawDeg = 5;
  c.pitchDeg = 7;
  c.rollDeg = -6;
  auto m = measureCorridor(c.shot());
  ASSERT_TRUE(m.ok()) << m.message();
  EXPECT_NEAR(signedDistancePx(m->horizon, m->vanishing.corridor.px), 0.0, 1e-4);
  EXPECT_GT(signedDistancePx(m->horizon, c.cornersPx()[P5]), 0.0);  // floor below it
  EXPECT_LT(signedDistancePx(m->horizon, c.cornersPx()[P7]), 0.0);  // ceiling above
}

}  // namespace
}  // namespace pw::metrology
