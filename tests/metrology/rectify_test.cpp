// Rectification: orientation of every plane, fidelity (PSNR) against a known
// texture, and no aliasing when shrinking.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "metrology/homography.h"
#include "metrology/measure.h"
#include "metrology/rectify.h"
#include "tests/metrology/synthetic_corridor.h"

namespace pw::metrology {
namespace {

using testing::Hit;
using testing::SyntheticCorridor;

double psnr(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat diff;
  cv::absdiff(a, b, diff);
  diff.convertTo(diff, CV_64F);
  const double mse = cv::mean(diff.mul(diff))[0];
  return 10 * std::log10(255.0 * 255.0 / std::max(mse, 1e-12));
}

// Every plane's texture runs the way rectify.h says: the photo encodes each hit's
// texture coordinates as colours (B = 255 s, G = 255 t, R = plane), so each texel of
// the result must hold its own position.
TEST(Rectify, EveryPlaneLandsTheWayTheHeaderSays) {
  SyntheticCorridor c;
  c.cameraXM = 0.3;
  c.yawDeg = 6;
  c.pitchDeg = -4;
  c.rollDeg = 3;
  const cv::Mat photo = testing::renderCorridor(c, [](const Hit& h) {
    return cv::Vec3d(255 * h.s, 255 * h.t, 40.0 * (h.plane + 1));
  });
  auto m = measureCorridor(c.shot());
  ASSERT_TRUE(m.ok()) << m.message();
  RectifyOptions options;
  options.pxPerM = 40;  // coarse: each texel averages several photo pixels on near planes
  auto planes = rectifyCorridor(photo, *m, options);
  ASSERT_TRUE(planes.ok()) << planes.message();
  for (int p = 0; p < kPlaneCount; ++p) {
    const cv::Mat& image = (*planes)[p].image;
    const glm::dvec2 size = planeSizeM(static_cast<Plane>(p), m->size);
    EXPECT_EQ(image.cols, std::lround(size.x * 40));
    EXPECT_EQ(image.rows, std::lround(size.y * 40));
    double errorS = 0, errorT = 0;
    int count = 0, wrongPlane = 0;
    // Texels near an edge of the plane mix with the next plane through bilinear and
    // pyramid filtering (a few texels), and where the photo stretches a texel to
    // under half a pixel the photo itself cannot place the edge: both are left out.
    const cv::Matx33d& h = (*planes)[p].photoFromTexture;
    for (int y = 4; y < image.rows - 4; ++y) {
      for (int x = 4; x < image.cols - 4; ++x) {
        const glm::dmat2 j = homographyJacobian(h, glm::dvec2(x, y));
        const double smallest = std::abs(j[0][0] * j[1][1] - j[1][0] * j[0][1]) / largestStretch(j);
        const double toEdgePx = smallest * std::min({x + 0.5, y + 0.5, image.cols - x - 0.5, image.rows - y - 0.5});
        if (toEdgePx < 2.0) continue;
        const cv::Vec3b px = image.at<cv::Vec3b>(y, x);
        errorS += std::abs(px[0] - 255.0 * (x + 0.5) / image.cols);
        errorT += std::abs(px[1] - 255.0 * (y + 0.5) / image.rows);
        wrongPlane += std::abs(px[2] - 40.0 * (p + 1)) > 8 ? 1 : 0;
        ++count;
      }
    }
    ASSERT_GT(count, image.total() / 3) << planeName(static_cast<Plane>(p));
    EXPECT_LT(errorS / count, 1.5) << planeName(static_cast<Plane>(p));
    EXPECT_LT(errorT / count, 1.5) << planeName(static_cast<Plane>(p));
    EXPECT_EQ(wrongPlane, 0) << planeName(static_cast<Plane>(p));
    EXPECT_DOUBLE_EQ((*planes)[p].coverage, 1.0);
  }
}

// A known texture on a wall seen at an angle, photographed (bilinear sampling of the
// texture at every photo pixel, the photo finer than the texture everywhere), then
// rectified back at the texture's resolution.
TEST(Rectify, RecoversAKnownTextureWithHighPsnr) {
  const int texW = 512, texH = 256;  // 2 m x 1 m at 256 px/m
  cv::Mat noise(texH / 8, texW / 8, CV_8UC3);
  cv::randu(noise, cv::Scalar::all(0), cv::Scalar::all(255));
  cv::Mat texture;
  cv::resize(noise, texture, cv::Size(texW, texH), 0, 0, cv::INTER_CUBIC);
  cv::GaussianBlur(texture, texture, cv::Size(0, 0), 1.5);
  // Photo: the texture's corners land on a perspective quad about 1.3 to 2x larger.
  const std::array<glm::dvec2, 4> quad{glm::dvec2(60, 40), glm::dvec2(1000, 140), glm::dvec2(1000, 560),
                                       glm::dvec2(60, 740)};
  std::array<glm::dvec2, 4> texCorners{glm::dvec2(-0.5, -0.5), glm::dvec2(texW - 0.5, -0.5),
                                       glm::dvec2(texW - 0.5, texH - 0.5), glm::dvec2(-0.5, texH - 0.5)};
  auto photoFromTexture = homographyFromCorners(texCorners, quad);
  ASSERT_TRUE(photoFromTexture.ok());
  cv::Mat photo;
  cv::warpPerspective(texture, photo, cv::Mat(*photoFromTexture), cv::Size(1060, 800), cv::INTER_LINEAR,
                      cv::BORDER_REPLICATE);
  RectifyOptions options;
  options.pxPerM = 256;
  auto r = rectifyPlane(photo, quad, 2.0, 1.0, options);
  ASSERT_TRUE(r.ok()) << r.message();
  ASSERT_EQ(r->image.size(), texture.size());
  const cv::Rect inner(4, 4, texW - 8, texH - 8);
  const double db = psnr(r->image(inner), texture(inner));
  std::printf("rectified vs known texture: PSNR %.1f dB\n", db);
  EXPECT_GT(db, 35.0);
  // Default resolution: the photo's best on the plane, at least the texture's here.
  auto automatic = rectifyPlane(photo, quad, 2.0, 1.0);
  ASSERT_TRUE(automatic.ok());
  EXPECT_GT(automatic->pxPerM, 256 * 1.3);
  EXPECT_LE(automatic->maxShrink, 1.01);
}

// Stripes finer than the output's pixels must average to grey, where plain bilinear
// warping turns them into a strong false pattern (moire).
TEST(Rectify, ShrinkingAveragesInsteadOfAliasing) {
  const int texW = 2048, texH = 1024;  // 2 m x 1 m, stripes 2 px wide
  cv::Mat texture(texH, texW, CV_8UC1);
  for (int x = 0; x < texW; ++x) texture.col(x).setTo(((x / 2) % 2) ? 230 : 25);
  const std::array<glm::dvec2, 4> quad{glm::dvec2(30, 20), glm::dvec2(2100, 200), glm::dvec2(2100, 900),
                                       glm::dvec2(30, 1100)};
  std::array<glm::dvec2, 4> texCorners{glm::dvec2(-0.5, -0.5), glm::dvec2(texW - 0.5, -0.5),
                                       glm::dvec2(texW - 0.5, texH - 0.5), glm::dvec2(-0.5, texH - 0.5)};
  auto h = homographyFromCorners(texCorners, quad);
  ASSERT_TRUE(h.ok());
  cv::Mat photo;
  cv::warpPerspective(texture, photo, cv::Mat(*h), cv::Size(2140, 1130), cv::INTER_AREA, cv::BORDER_REPLICATE);
  RectifyOptions options;
  options.pxPerM = 97;  // about 11 photo pixels per texel: 5 stripe periods
  auto r = rectifyPlane(photo, quad, 2.0, 1.0, options);
  ASSERT_TRUE(r.ok()) << r.message();
  EXPECT_GT(r->maxShrink, 8.0);
  // Baseline: the same homography warped in one go with bilinear sampling.
  cv::Mat plain;
  cv::warpPerspective(photo, plain, cv::Mat(r->photoFromTexture), r->image.size(), cv::INTER_LINEAR | cv::WARP_INVERSE_MAP,
                      cv::BORDER_REPLICATE);
  cv::Scalar meanOurs, sdOurs, meanPlain, sdPlain;
  const cv::Rect inner(2, 2, r->image.cols - 4, r->image.rows - 4);
  cv::meanStdDev(r->image(inner), meanOurs, sdOurs);
  cv::meanStdDev(plain(inner), meanPlain, sdPlain);
  std::printf("stripes shrunk 11x: std %.1f (antialiased) vs %.1f (plain bilinear)\n", sdOurs[0], sdPlain[0]);
  EXPECT_NEAR(meanOurs[0], 127.5, 6.0);
  EXPECT_LT(sdOurs[0], 8.0);
  EXPECT_GT(sdPlain[0], 4 * sdOurs[0]);
}

TEST(Rectify, CapsTheLongerSide) {
  SyntheticCorridor c;
  const cv::Mat photo(c.imageHeight, c.imageWidth, CV_8UC3, cv::Scalar(90, 120, 150));
  auto m = measureCorridor(c.shot());
  ASSERT_TRUE(m.ok());
  RectifyOptions options;
  options.maxSidePx = 300;
  auto planes = rectifyCorridor(photo, *m, options);
  ASSERT_TRUE(planes.ok()) << planes.message();
  for (const auto& p : *planes) {
    EXPECT_LE(std::max(p.image.cols, p.image.rows), 300);
    EXPECT_EQ(p.image.at<cv::Vec3b>(p.image.rows / 2, p.image.cols / 2), cv::Vec3b(90, 120, 150));
  }
}

TEST(Rectify, BadInputIsRefused) {
  const cv::Mat photo(100, 100, CV_8UC3, cv::Scalar::all(0));
  const std::array<glm::dvec2, 4> quad{glm::dvec2(10, 10), glm::dvec2(90, 10), glm::dvec2(90, 90), glm::dvec2(10, 90)};
  EXPECT_FALSE(rectifyPlane(cv::Mat(), quad, 1, 1).ok());
  EXPECT_FALSE(rectifyPlane(photo, quad, 0, 1).ok());
  EXPECT_FALSE(rectifyPlane(photo, quad, 1, std::nan("")).ok());
  std::array<glm::dvec2, 4> crossed = quad;
  std::swap(crossed[0], crossed[1]);
  auto r = rectifyPlane(photo, crossed, 1, 1);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.message().find("cross"), std::string::npos);
  std::array<glm::dvec2, 4> collinear = quad;
  collinear[2] = glm::dvec2(170, 10);
  EXPECT_FALSE(rectifyPlane(photo, collinear, 1, 1).ok());
  const std::array<glm::dvec2, 4> outside{glm::dvec2(1000, 1000), glm::dvec2(1090, 1000), glm::dvec2(1090, 1090),
                                          glm::dvec2(1000, 1090)};
  r = rectifyPlane(photo, outside, 1, 1);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.message().find("outside the photo"), std::string::npos);
}

TEST(Homography, MatchesOpenCvAndMapsTheCorners) {
  const std::array<glm::dvec2, 4> src{glm::dvec2(0, 0), glm::dvec2(3, 0), glm::dvec2(3, 2), glm::dvec2(0, 2)};
  const std::array<glm::dvec2, 4> dst{glm::dvec2(100, 80), glm::dvec2(400, 130), glm::dvec2(380, 300),
                                      glm::dvec2(90, 420)};
  auto h = homographyFromCorners(src, dst);
  ASSERT_TRUE(h.ok());
  std::vector<cv::Point2f> s, d;
  for (int i = 0; i < 4; ++i) {
    EXPECT_LT(glm::length(applyHomography(*h, src[i]) - dst[i]), 1e-9);
    s.emplace_back(static_cast<float>(src[i].x), static_cast<float>(src[i].y));
    d.emplace_back(static_cast<float>(dst[i].x), static_cast<float>(dst[i].y));
  }
  const cv::Mat reference = cv::getPerspectiveTransform(s, d);
  for (int r = 0; r < 3; ++r) {
    for (int col = 0; col < 3; ++col) EXPECT_NEAR((*h)(r, col), reference.at<double>(r, col), 1e-4 * (1 + std::abs((*h)(r, col))));
  }
  // Jacobian against a finite difference.
  const glm::dvec2 p(1.2, 0.7);
  const glm::dmat2 j = homographyJacobian(*h, p);
  const glm::dvec2 dx = (applyHomography(*h, p + glm::dvec2(1e-6, 0)) - applyHomography(*h, p - glm::dvec2(1e-6, 0))) / 2e-6;
  EXPECT_NEAR(j[0].x, dx.x, 1e-5);
  EXPECT_NEAR(j[0].y, dx.y, 1e-5);
}

}  // namespace
}  // namespace pw::metrology
