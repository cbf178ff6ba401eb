// Texture synthesis (modeling/synthesis.h) on textures whose truth is known: what the
// "photo" does not show is filled from what it shows, continuing a periodic pattern
// by whole periods (exactly, where the photo showed it exactly) and mirroring one that
// does not repeat.
#include "modeling/synthesis.h"

#include <gtest/gtest.h>

#include <cmath>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace pw::modeling {
namespace {

constexpr int kWidth = 600, kHeight = 64, kShownFrom = 200;  // the photo shows x >= 200

// Texel (x, y) lands on photo pixel (x - 200, y + 10) of a 400 x 84 photo: one photo
// pixel a texel, the columns before 200 outside the photo, every row well inside it.
std::optional<glm::dvec2> photoOf(double x, double y) { return glm::dvec2(x - kShownFrom, y + 10); }
const cv::Size kPhoto(kWidth - kShownFrom, kHeight + 20);

// Bricks: mortar columns every 25 texels, mortar rows every 16, offset by half a brick
// every other course.
cv::Mat3b bricks() {
  cv::Mat3b t(kHeight, kWidth);
  for (int y = 0; y < kHeight; ++y) {
    const int shift = (y / 16) % 2 ? 12 : 0;
    for (int x = 0; x < kWidth; ++x) {
      const bool mortar = (x + shift) % 25 < 3 || y % 16 < 2;
      t(y, x) = mortar ? cv::Vec3b(190, 200, 205) : cv::Vec3b(40, 60, 140);
    }
  }
  return t;
}

TEST(Synthesis, APeriodicSurfaceContinuesByWholePeriods) {
  const cv::Mat3b truth = bricks();
  cv::Mat texture = truth.clone();
  texture(cv::Rect(0, 0, kShownFrom, kHeight)).setTo(cv::Scalar::all(128));  // unseen: the rectifier's flat fill
  const SynthesisStats stats = synthesizeSurface(texture, photoOf, kPhoto);
  EXPECT_EQ(stats.periodPx, 25);
  EXPECT_GT(stats.exemplarColumns, 300);
  EXPECT_NEAR(stats.filledFraction, (kShownFrom + 2.0) / kWidth, 0.01) << "the unseen columns and the photo's 2 px border";
  cv::Mat diff;
  cv::absdiff(texture(cv::Rect(0, 0, kShownFrom, kHeight)), truth(cv::Rect(0, 0, kShownFrom, kHeight)), diff);
  const double meanError = cv::mean(diff.reshape(1))[0];
  std::printf("periodic fill: period %d texels, mean error %.3f of 255\n", stats.periodPx, meanError);
  EXPECT_LT(meanError, 0.5) << "the bricks carry on as they were";
  // What the photo showed is left as it was.
  EXPECT_EQ(cv::norm(cv::Mat(texture)(cv::Rect(kShownFrom + 2, 0, kWidth - kShownFrom - 4, kHeight)),
                     cv::Mat(truth)(cv::Rect(kShownFrom + 2, 0, kWidth - kShownFrom - 4, kHeight)), cv::NORM_INF),
            0.0);
}

TEST(Synthesis, ASurfaceThatDoesNotRepeatIsMirroredWithoutASeam) {
  cv::Mat3b noise(kHeight, kWidth);
  cv::RNG rng(7);
  rng.fill(noise, cv::RNG::NORMAL, cv::Scalar::all(128), cv::Scalar::all(20));
  cv::Mat3b smooth;
  cv::GaussianBlur(noise, smooth, {0, 0}, 1.5);
  cv::Mat texture = smooth.clone();
  texture(cv::Rect(0, 0, kShownFrom, kHeight)).setTo(cv::Scalar::all(128));
  const SynthesisStats stats = synthesizeSurface(texture, photoOf, kPhoto);
  EXPECT_EQ(stats.periodPx, 0);
  const cv::Mat3b t = texture;
  const int edge = kShownFrom + 2;  // the first column shown (less the border)
  for (int k = 0; k < 20; ++k) {
    if (k < 2) {
      // The border's two columns lend nothing but stay the photo's own (the photo's
      // camera sees them).
      EXPECT_EQ(cv::norm(cv::Mat(t.col(edge - 1 - k)), cv::Mat(smooth.col(edge - 1 - k)), cv::NORM_INF), 0.0) << k;
      continue;
    }
    // Mirrored about the edge: the k-th column before it is the k-th after it.
    EXPECT_EQ(cv::norm(cv::Mat(t.col(edge - 1 - k)), cv::Mat(t.col(edge + k)), cv::NORM_INF), 0.0) << k;
  }
  // No flat colour left where the photo saw nothing: as varied as what it saw.
  cv::Scalar filledMean, filledStd, shownMean, shownStd;
  cv::meanStdDev(texture(cv::Rect(0, 0, kShownFrom, kHeight)), filledMean, filledStd);
  cv::meanStdDev(texture(cv::Rect(edge, 0, kWidth - edge, kHeight)), shownMean, shownStd);
  EXPECT_GT(filledStd[0], 0.7 * shownStd[0]);
}

TEST(Synthesis, NothingShownLeavesTheTextureAsItIs) {
  cv::Mat texture(kHeight, kWidth, CV_8UC3, cv::Scalar(10, 20, 30));
  const cv::Mat before = texture.clone();
  const auto nowhere = [](double, double) -> std::optional<glm::dvec2> { return std::nullopt; };
  const SynthesisStats stats = synthesizeSurface(texture, nowhere, kPhoto);
  EXPECT_EQ(stats.exemplarColumns, 0);
  EXPECT_EQ(stats.filledFraction, 0.0);
  EXPECT_EQ(cv::norm(texture, before, cv::NORM_INF), 0.0);
}

}  // namespace
}  // namespace pw::modeling
