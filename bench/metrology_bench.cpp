#include "bench/bench_timing.h"
// metrology_bench: measure and rectify on a 12-megapixel photo, medians.
//
// The photo is the sample corridor (assets/corridor.png, 1280x720) upscaled to about
// 12 MP with bicubic interpolation, its corners and focal length scaled with it.
// Baseline, in the same run: a plain one-shot bilinear cv::warpPerspective of the
// same five planes at the same sizes (no antialiasing, no tiling), i.e. what the
// antialiasing costs. Target: rectify (all five planes) under 1 s on 2 cores.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "bench/bench_timing.h"
#include "metrology/measure.h"
#include "metrology/rectify.h"

namespace {

using namespace pw::metrology;
using pw::bench::medianMs;


// The sample shot's corners (assets/corridor.json) in its 1280x720 photo.
constexpr double kCorners[kCornerCount][2] = {{537.1304, 293.6909}, {683.3727, 293.6909}, {537.1304, 421.653},
                                              {683.3727, 421.653},  {212.9598, 618.4708}, {822.3029, 618.4708},
                                              {212.9598, 85.2956},  {822.3029, 85.2956}};

}  // namespace

int main() {
  const cv::Mat sample = cv::imread(PW_SOURCE_DIR "/assets/corridor.png", cv::IMREAD_COLOR);
  if (sample.empty()) {
    std::fprintf(stderr, "error: %s/assets/corridor.png is missing\n", PW_SOURCE_DIR);
    return 1;
  }
  const double scale = std::sqrt(12e6 / (static_cast<double>(sample.cols) * sample.rows));
  cv::Mat photo;
  cv::resize(sample, photo, cv::Size(static_cast<int>(std::lround(sample.cols * scale)),
                                     static_cast<int>(std::lround(sample.rows * scale))),
             0, 0, cv::INTER_CUBIC);
  const double sx = static_cast<double>(photo.cols) / sample.cols, sy = static_cast<double>(photo.rows) / sample.rows;
  Shot shot;
  shot.imagePath = "corridor.png (upscaled)";
  shot.imageWidth = photo.cols;
  shot.imageHeight = photo.rows;
  shot.focalPx = 914.014724 * sx;
  shot.cameraHeightM = 1.7;
  for (int i = 0; i < kCornerCount; ++i) {
    // Pixel centres at integer coordinates: scale about the image's outer corner.
    shot.cornersPx[i] = glm::dvec2((kCorners[i][0] + 0.5) * sx - 0.5, (kCorners[i][1] + 0.5) * sy - 0.5);
  }
  std::printf("photo %dx%d (%.1f MP), OpenCV threads %d, %d runs each, medians\n", photo.cols, photo.rows,
              photo.total() / 1e6, cv::getNumThreads(), 11);

  auto measured = measureCorridor(shot);
  if (!measured) {
    std::fprintf(stderr, "error: %s\n", measured.message().c_str());
    return 1;
  }
  MeasureOptions seed;
  seed.method = Method::kSeed;
  const double measureMs = medianMs(11, [&] { (void)measureCorridor(shot); });
  const double seedMs = medianMs(11, [&] { (void)measureCorridor(shot, seed); });
  std::printf("measure (general)        %8.2f ms   W %.3f H %.3f L %.3f m\n", measureMs, measured->size.widthM,
              measured->size.heightM, measured->size.lengthM);
  std::printf("measure (seed)           %8.2f ms\n", seedMs);

  auto planes = rectifyCorridor(photo, *measured);
  if (!planes) {
    std::fprintf(stderr, "error: %s\n", planes.message().c_str());
    return 1;
  }
  double megapixels = 0;
  for (const auto& p : *planes) megapixels += p.image.total() / 1e6;
  const double rectifyMs = medianMs(11, [&] { (void)rectifyCorridor(photo, *measured); });
  // Baseline: one plain bilinear warp per plane at the same sizes.
  const double plainMs = medianMs(11, [&] {
    for (const auto& p : *planes) {
      cv::Mat out;
      cv::warpPerspective(photo, out, cv::Mat(p.photoFromTexture), p.image.size(), cv::INTER_LINEAR | cv::WARP_INVERSE_MAP,
                          cv::BORDER_REPLICATE);
    }
  });
  std::printf("rectify, 5 planes        %8.2f ms   %.1f MP of texture (", rectifyMs, megapixels);
  for (int p = 0; p < kPlaneCount; ++p) {
    std::printf("%s%dx%d", p ? ", " : "", (*planes)[p].image.cols, (*planes)[p].image.rows);
  }
  std::printf(")\n");
  std::printf("baseline: plain warp     %8.2f ms   (no antialiasing; rectify costs %.2fx)\n", plainMs, rectifyMs / plainMs);
  std::printf("rectify under 1 s: %s\n", rectifyMs < 1000 ? "yes" : "NO");
  return rectifyMs < 1000 ? 0 : 1;
}
