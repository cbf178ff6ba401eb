// Lens distortion (metrology/distortion.h): the model against OpenCV's own
// projectPoints, measure through the lens on synthetic corridors with known answers,
// and the rectifier sampling a distorted photo through it.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "metrology/distortion.h"
#include "metrology/least_squares.h"
#include "metrology/measure.h"
#include "metrology/rectify.h"
#include "tests/metrology/synthetic_corridor.h"

namespace pw::metrology {
namespace {

using testing::Hit;
using testing::SyntheticCorridor;
using testing::renderCorridor;

Intrinsics lensOf(const SyntheticCorridor& c, double k1, double k2 = 0) {
  Intrinsics k = c.intrinsics();
  k.distortion = {k1, k2};
  return k;
}

// The shot of `c` photographed through the lens: its corners where the lens puts them.
Shot distortedShot(const SyntheticCorridor& c, const Intrinsics& lens) {
  Shot s = c.shot();
  for (glm::dvec2& p : s.cornersPx) p = distortPixel(lens, p);
  s.distortion = lens.distortion;
  return s;
}

TEST(Distortion, MatchesOpenCvsProjection) {
  SyntheticCorridor c;
  const Intrinsics lens = lensOf(c, -0.2, 0.05);
  const cv::Matx33d k(c.focalPx, 0, lens.principalPointPx.x, 0, c.focalPx, lens.principalPointPx.y, 0, 0, 1);
  for (const glm::dvec2 p : {glm::dvec2(10, 20), glm::dvec2(700, 550), glm::dvec2(399.5, 299.5), glm::dvec2(-50, 300)}) {
    // A point at depth 1 in OpenCV's camera frame that the pinhole puts at p.
    const glm::dvec2 x = (p - lens.principalPointPx) / c.focalPx;
    std::vector<cv::Point3d> object{{x.x, x.y, 1.0}};
    std::vector<cv::Point2d> image;
    cv::projectPoints(object, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), k, cv::Matx<double, 1, 4>(-0.2, 0.05, 0, 0), image);
    const glm::dvec2 d = distortPixel(lens, p);
    EXPECT_NEAR(d.x, image[0].x, 1e-9);
    EXPECT_NEAR(d.y, image[0].y, 1e-9);
    const auto back = undistortPixel(lens, d);
    ASSERT_TRUE(back.has_value());
    EXPECT_NEAR(back->x, p.x, 1e-6);
    EXPECT_NEAR(back->y, p.y, 1e-6);
  }
}

TEST(Distortion, MinimizeOnIntervalFindsTheGlobalMinimum) {
  // Two minima, the deeper at 0.123; undefined (infinite) below -0.4.
  const auto f = [](double x) {
    return x < -0.4 ? INFINITY : std::min((x - 0.123) * (x - 0.123), 0.01 + (x + 0.3) * (x + 0.3));
  };
  EXPECT_NEAR(minimizeOnInterval(f, -0.5, 0.3, 16, 40, 0.0), 0.123, 1e-6);
  EXPECT_NEAR(minimizeOnInterval(f, -0.5, 0.3, 16, 40, -0.3), 0.123, 1e-6);
}

TEST(Distortion, NoneIsThePinholeExactly) {
  SyntheticCorridor c;
  const Intrinsics pinhole = c.intrinsics();
  const glm::dvec2 p(123.456789, 654.321);
  EXPECT_EQ(distortPixel(pinhole, p), p);
  EXPECT_EQ(undistortPixel(pinhole, p), p);
}

TEST(Distortion, BeyondTheFoldDoesNotInvert) {
  SyntheticCorridor c;
  const Intrinsics lens = lensOf(c, -0.2);  // folds at r = 1.29 (r_d 0.86 of the focal length)
  EXPECT_FALSE(undistortPixel(lens, lens.principalPointPx + glm::dvec2(0.95 * c.focalPx, 0)).has_value());
  EXPECT_TRUE(undistortPixel(lens, lens.principalPointPx + glm::dvec2(0.8 * c.focalPx, 0)).has_value());
  EXPECT_FALSE(insideFold(lens, lens.principalPointPx + glm::dvec2(1.3 * c.focalPx, 0)));
  EXPECT_TRUE(insideFold(lens, lens.principalPointPx + glm::dvec2(1.2 * c.focalPx, 0)));
}

TEST(Distortion, MeasureThroughTheLensIsExact) {
  for (double k1 : {-0.1, -0.2, 0.05}) {
    SyntheticCorridor c;
    c.yawDeg = 6, c.pitchDeg = -3, c.rollDeg = 4, c.cameraXM = 0.3;
    const Intrinsics lens = lensOf(c, k1, k1 == -0.2 ? 0.02 : 0.0);
    auto m = measureCorridor(distortedShot(c, lens));
    ASSERT_TRUE(m.ok()) << m.message();
    EXPECT_NEAR(m->size.widthM, c.widthM, 1e-6 * c.widthM) << k1;
    EXPECT_NEAR(m->size.heightM, c.heightM, 1e-6 * c.heightM) << k1;
    EXPECT_NEAR(m->size.lengthM, c.lengthM, 1e-6 * c.lengthM) << k1;
    EXPECT_LT(m->reprojectionRmsPx, 1e-4) << k1;
    EXPECT_EQ(m->distortionSource, DistortionSource::kShot);
    EXPECT_EQ(m->camera.distortion.k1, k1);
    // The reprojection is the photo's: through the lens onto the distorted corners.
    const Shot s = distortedShot(c, lens);
    for (int i = 0; i < kCornerCount; ++i) EXPECT_NEAR(glm::length(m->reprojectedPx[i] - s.cornersPx[i]), 0, 1e-4);
    const glm::dvec3 p = projectWithMeasurement(*m, c.cornersM()[P5]);
    EXPECT_NEAR(glm::length(glm::dvec2(p) - s.cornersPx[P5]), 0, 1e-4);
  }
}

TEST(Distortion, WithoutItTheLensBiasesTheBox) {
  // What the lens does to a measurement that ignores it (today's measure), so that
  // the exact answer above is not the pinhole's by chance.
  SyntheticCorridor c;
  c.cameraXM = 0.3;
  Shot s = distortedShot(c, lensOf(c, -0.2));
  s.distortion = RadialDistortion{};  // known to be none: no estimate either
  auto m = measureCorridor(s);
  ASSERT_TRUE(m.ok()) << m.message();
  EXPECT_GT(std::abs(m->size.lengthM / c.lengthM - 1.0), 0.005);
}

TEST(Distortion, MeasureFindsTheLensInTheCornersResidual) {
  // A turned camera off the centre line: the box's corners through a lens do not fit a
  // pinhole's box, and a k1 explains that.
  SyntheticCorridor c;
  c.yawDeg = 8, c.pitchDeg = -5, c.rollDeg = 3, c.cameraXM = 0.4;
  for (double k1 : {-0.1, -0.2}) {
    Shot s = distortedShot(c, lensOf(c, k1));
    s.distortion.reset();  // not known
    auto m = measureCorridor(s);
    ASSERT_TRUE(m.ok()) << m.message();
    EXPECT_EQ(m->distortionSource, DistortionSource::kCorners) << k1;
    EXPECT_NEAR(m->camera.distortion.k1, k1, 1e-4);
    EXPECT_NEAR(m->size.lengthM, c.lengthM, 1e-4 * c.lengthM);
    MeasureOptions pinholeOnly;
    pinholeOnly.distortionFromCorners = false;
    auto without = measureCorridor(s, pinholeOnly);
    ASSERT_TRUE(without.ok());
    EXPECT_EQ(without->distortionSource, DistortionSource::kNone);
    EXPECT_GT(without->reprojectionRmsPx, kDistortionResidualPx);
    std::printf("[distortion] corners' residual, k1 %.2f: %.2f px without a lens, found k1 %.5f; length %+.3f%% -> %+.5f%%\n",
                k1, without->reprojectionRmsPx, m->camera.distortion.k1, 100 * (without->size.lengthM / c.lengthM - 1),
                100 * (m->size.lengthM / c.lengthM - 1));
  }
}

TEST(Distortion, MeasureInventsNoLensForAMisplacedCorner) {
  SyntheticCorridor c;
  c.yawDeg = 8, c.pitchDeg = -5, c.rollDeg = 3, c.cameraXM = 0.4;
  for (int corner : {P1, P3, P5, P8}) {
    for (const glm::dvec2 nudge : {glm::dvec2(3, 0), glm::dvec2(0, -6), glm::dvec2(8, 8), glm::dvec2(-12, 5)}) {
      Shot s = c.shot();
      s.cornersPx[corner] += nudge;
      auto m = measureCorridor(s);
      ASSERT_TRUE(m.ok()) << m.message();
      EXPECT_EQ(m->distortionSource, DistortionSource::kNone) << cornerName(corner) << " k1 " << m->camera.distortion.k1;
      EXPECT_GT(m->reprojectionRmsPx, kDistortionResidualPx) << cornerName(corner);
    }
  }
  // Nor for exact corners of a pinhole (nothing to explain), nor a lens known to be none.
  auto exact = measureCorridor(c.shot());
  ASSERT_TRUE(exact.ok());
  EXPECT_EQ(exact->distortionSource, DistortionSource::kNone);
  Shot known = distortedShot(c, lensOf(c, -0.2));
  known.distortion = RadialDistortion{};
  auto none = measureCorridor(known);
  ASSERT_TRUE(none.ok());
  EXPECT_EQ(none->distortionSource, DistortionSource::kShot);
  EXPECT_TRUE(none->camera.distortion.isNone());
}

TEST(Distortion, BadCoefficientsAreOneLineErrors) {
  SyntheticCorridor c;
  Shot s = c.shot();
  s.distortion = RadialDistortion{std::nan(""), 0};
  auto m = measureCorridor(s);
  ASSERT_FALSE(m.ok());
  EXPECT_NE(m.message().find("distortion"), std::string::npos) << m.message();
  // A corner beyond where the lens folds back cannot be undistorted.
  s = c.shot();
  s.distortion = RadialDistortion{-1.5, 0};  // folds at 0.31 of the focal length from the centre
  m = measureCorridor(s);
  ASSERT_FALSE(m.ok());
  EXPECT_NE(m.message().find("does not invert"), std::string::npos) << m.message();
}

// A checkerboard corridor rendered by ray casting, and the same photo through the lens
// (each photo pixel the pinhole's pixel the lens brings there).
cv::Mat checkerPhoto(const SyntheticCorridor& c, const Intrinsics& lens) {
  const auto shade = [](const Hit& hit) {
    const bool dark = (static_cast<int>(hit.s * 8) + static_cast<int>(hit.t * 8)) % 2;
    return dark ? cv::Vec3d(40, 60, 90) : cv::Vec3d(210, 220, 230);
  };
  SyntheticCorridor wide = c;
  // Rendered twice as large about the same principal point, then taken through the lens.
  wide.imageWidth = 2 * c.imageWidth, wide.imageHeight = 2 * c.imageHeight;
  const cv::Mat pinhole = renderCorridor(wide, shade, 2);
  cv::Mat mapX, mapY, photo;
  const glm::dvec2 offset = wide.principalPointPx() - c.principalPointPx();
  distortionMaps(lens, cv::Size(c.imageWidth, c.imageHeight), offset, mapX, mapY);
  cv::remap(pinhole, photo, mapX, mapY, cv::INTER_CUBIC, cv::BORDER_CONSTANT);
  return photo;
}

double psnr(const cv::Mat& a, const cv::Mat& b) { return cv::PSNR(a, b); }

TEST(Distortion, RectifyThroughTheLensGivesThePinholesTextures) {
  SyntheticCorridor c;
  c.yawDeg = 4, c.cameraXM = 0.2;
  const Intrinsics lens = lensOf(c, -0.15);
  const cv::Mat pinholePhoto = checkerPhoto(c, c.intrinsics());
  const cv::Mat distortedPhoto = checkerPhoto(c, lens);
  auto pinhole = measureCorridor(c.shot());
  auto through = measureCorridor(distortedShot(c, lens));
  ASSERT_TRUE(pinhole.ok() && through.ok());
  RectifyOptions options;
  options.pxPerM = 60;
  auto expected = rectifyCorridor(pinholePhoto, *pinhole, options);
  auto got = rectifyCorridor(distortedPhoto, *through, options);
  auto ignored = rectifyCorridor(distortedPhoto, *pinhole, options);  // the lens left out
  ASSERT_TRUE(expected.ok() && got.ok() && ignored.ok());
  for (int p = 0; p < kPlaneCount; ++p) {
    ASSERT_EQ((*got)[p].image.size(), (*expected)[p].image.size());
    const double withLens = psnr((*got)[p].image, (*expected)[p].image);
    const double without = psnr((*ignored)[p].image, (*expected)[p].image);
    EXPECT_GT(withLens, 28.0) << planeName(static_cast<Plane>(p));
    EXPECT_GT(withLens, without + 6.0) << planeName(static_cast<Plane>(p));
  }
}

}  // namespace
}  // namespace pw::metrology
