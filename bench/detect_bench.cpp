// Speed of `photowalk detect` (issues 7 and 15: under 300 ms on a 12-megapixel photo
// on two cores). Prints medians of several runs, with baselines from the same run:
// LSD run directly on the full-resolution photo (what detection would cost without
// the working copy), the stages of the pipeline, and a cluttered corridor (where the
// angular profile fails and the room's box is fitted) against the clean one. Besides wall time it prints the
// process's CPU time (all threads): on a shared, busy machine wall time measures the
// neighbours too, while CPU time bounds what two idle cores would take.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <vector>

#include <time.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "metrology/detect/detect.h"
#include "metrology/detect/layout_net.h"
#include "metrology/detect/line_segments.h"
#include "metrology/detect/room_box.h"
#include "metrology/detect/vanishing_points.h"
#include "metrology/detect/working_image.h"
#include "modeling/shot_file.h"

namespace {

using Clock = std::chrono::steady_clock;

struct Timing {
  double wallMs = 0;
  double cpuMs = 0;
};

double cpuNowMs() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

Timing median(int runs, const std::function<void()>& work) {
  std::vector<double> wall, cpu;
  for (int i = 0; i < runs; ++i) {
    const auto t0 = Clock::now();
    const double c0 = cpuNowMs();
    work();
    cpu.push_back(cpuNowMs() - c0);
    wall.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
  }
  std::sort(wall.begin(), wall.end());
  std::sort(cpu.begin(), cpu.end());
  return {wall[wall.size() / 2], cpu[cpu.size() / 2]};
}

// An 800x600 scene scaled 5x to 4000x3000, with sensor-like noise so edges are not
// unnaturally clean.
cv::Mat twelveMegapixels(const cv::Mat& small) {
  cv::Mat big;
  cv::resize(small, big, cv::Size(4000, 3000), 0, 0, cv::INTER_CUBIC);
  cv::Mat noise(big.size(), CV_8UC3);
  cv::randn(noise, 0, 3);
  cv::add(big, noise, big);
  return big;
}

}  // namespace

int main() {
  using namespace pw::metrology::detect;
  const std::string path = std::string(PW_GROUNDTRUTH_DIR) + "/corridor_a.png";
  const cv::Mat small = cv::imread(path, cv::IMREAD_COLOR);
  if (small.empty()) {
    std::fprintf(stderr, "error: %s not found (the build renders it: target groundtruth)\n", path.c_str());
    return 1;
  }
  constexpr double kFocalSmall = 692.820323;
  // 12 megapixels: the 800x600 corridor scaled 5x to 4000x3000, with sensor-like noise
  // so edges are not unnaturally clean.
  const cv::Mat big = twelveMegapixels(small);

  std::printf("detect_bench: %d OpenCV threads; medians, wall ms / process CPU ms\n", cv::getNumThreads());
  DetectOptions options;
  options.focalPx = kFocalSmall * 5;
  bool found = false;
  const Timing full = median(9, [&] { found = detectCorridor(big, options)->found; });
  std::printf("  detectCorridor, 4000x3000 (12 MP)           %8.1f / %8.1f  (found: %s; target < 300 ms)\n", full.wallMs,
              full.cpuMs, found ? "yes" : "NO");

  // The plumb-line fit (metrology/detect/distortion.h) runs on every photo: the same
  // detection without it is its baseline.
  DetectOptions pinholeOnly = options;
  pinholeOnly.estimateDistortion = false;
  const Timing withoutLens = median(9, [&] { (void)detectCorridor(big, pinholeOnly); });
  std::printf("  baseline: the same without the lens fit      %8.1f / %8.1f  (the fit: %+.1f / %+.1f)\n", withoutLens.wallMs,
              withoutLens.cpuMs, full.wallMs - withoutLens.wallMs, full.cpuMs - withoutLens.cpuMs);
  // A 12 MP photo through a barrel lens (k1 -0.2): the fit finds it, and detection runs
  // again on the photo undistorted.
  cv::Mat mapX(big.size(), CV_32FC1), mapY(big.size(), CV_32FC1), distorted;
  const double f = kFocalSmall * 5, cx = (big.cols - 1) * 0.5, cy = (big.rows - 1) * 0.5;
  for (int y = 0; y < big.rows; ++y) {
    for (int x = 0; x < big.cols; ++x) {
      // The inverse of the lens by fixed-point iteration (what the photo shows at x, y).
      const double xd = (x - cx) / f, yd = (y - cy) / f;
      double xu = xd, yu = yd;
      for (int i = 0; i < 20; ++i) {
        const double factor = 1 - 0.2 * (xu * xu + yu * yu);
        xu = xd / factor, yu = yd / factor;
      }
      mapX.at<float>(y, x) = static_cast<float>(cx + f * xu);
      mapY.at<float>(y, x) = static_cast<float>(cy + f * yu);
    }
  }
  cv::remap(big, distorted, mapX, mapY, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  bool lensFound = false;
  const Timing throughLens = median(5, [&] { lensFound = !detectCorridor(distorted, options)->distortion.isNone(); });
  std::printf("  detectCorridor, 12 MP through k1 -0.2        %8.1f / %8.1f  (lens found: %s; target < 300 ms)\n", throughLens.wallMs,
              throughLens.cpuMs, lensFound ? "yes" : "NO");

  WorkingImage work;
  const Timing prepare = median(9, [&] { work = makeWorkingImage(big, DetectOptions{}.workingMaxSidePx); });
  std::printf("    stage: working copy %dx%d + gradients  %8.1f / %8.1f\n", work.bgr.cols, work.bgr.rows, prepare.wallMs,
              prepare.cpuMs);
  const double diagonal = std::hypot(big.cols, big.rows);
  const Timing lsdWorking = median(9, [&] { (void)detectLineSegments(work.gray, work.scale, 0.02 * diagonal); });
  std::printf("    stage: LSD on the working copy             %8.1f / %8.1f\n", lsdWorking.wallMs, lsdWorking.cpuMs);
  std::printf("    the rest (frame, boundaries, far wall, full-resolution fits) ~ %.1f / %.1f\n",
              full.wallMs - prepare.wallMs - lsdWorking.wallMs, full.cpuMs - prepare.cpuMs - lsdWorking.cpuMs);

  cv::Mat grayFull;
  cv::cvtColor(big, grayFull, cv::COLOR_BGR2GRAY);
  const Timing lsdFull = median(3, [&] { (void)detectLineSegments(grayFull, 1.0, 0.02 * diagonal); });
  std::printf("  baseline: LSD alone on the full 12 MP photo  %8.1f / %8.1f  (%.1fx the whole detection)\n",
              lsdFull.wallMs, lsdFull.cpuMs, lsdFull.wallMs / full.wallMs);

  // Issue 15: a cluttered corridor, where the room's box is fitted too (clutter_1:
  // cabinets, a person and a door before the far wall), at 12 MP, against the clean
  // corridor above.
  const std::string clutterPath = std::string(PW_GROUNDTRUTH_DIR) + "/clutter_1.png";
  const cv::Mat clutterSmall = cv::imread(clutterPath, cv::IMREAD_COLOR);
  if (clutterSmall.empty()) {
    std::fprintf(stderr, "error: %s not found (the build renders it: target groundtruth)\n", clutterPath.c_str());
    return 1;
  }
  const cv::Mat clutterBig = twelveMegapixels(clutterSmall);
  DetectOptions clutterOptions;
  clutterOptions.focalPx = 660.0 * 5;
  bool clutterFound = false;
  const Timing clutter = median(9, [&] { clutterFound = detectCorridor(clutterBig, clutterOptions)->found; });
  std::printf("  detectCorridor, 12 MP cluttered (clutter_1)  %8.1f / %8.1f  (found: %s; %+.1f / %+.1f against the clean one)\n",
              clutter.wallMs, clutter.cpuMs, clutterFound ? "yes" : "NO", clutter.wallMs - full.wallMs,
              clutter.cpuMs - full.cpuMs);
  const WorkingImage clutterWork = makeWorkingImage(clutterBig, DetectOptions{}.workingMaxSidePx);
  const auto clutterSegments = detectLineSegments(clutterWork.gray, clutterWork.scale, 0.02 * diagonal);
  auto frame = estimateManhattanFrame(clutterSegments, PinholeCamera{clutterOptions.focalPx.value(),
                                                                     glm::dvec2(1999.5, 1499.5)}, clutterBig.size());
  if (!frame) {
    std::fprintf(stderr, "error: no Manhattan frame in the cluttered photo: %s\n", frame.message().c_str());
    return 1;
  }
  const glm::dvec2 vpWork = clutterWork.toWorking(frame->corridor.pixel());
  const Timing box = median(9, [&] {
    (void)fitRoomBox(clutterWork, vpWork, clutterWork.toWorking(frame->horizontal.point),
                     clutterWork.toWorking(frame->vertical.point), clutterSegments, frame->labels);
  });
  std::printf("    stage: the room's box on the working copy  %8.1f / %8.1f\n", box.wallMs, box.cpuMs);
  // The layout networks (layout_net.h), asked where the edges' answer is not sure (as
  // here): the whole photo and the far wall's neighbourhood, each 192 x 192, and the box
  // fitted to each.
  const pw::metrology::detect::CorridorAxes axes = corridorAxes(
      frame->horizontal.point, frame->vertical.point, frame->corridor.point, clutterOptions.focalPx.value(), glm::dvec2(1999.5, 1499.5));
  const Timing layout = median(9, [&] {
    (void)fitLayout(clutterWork.bgr, clutterWork.scale, clutterOptions.focalPx.value(), glm::dvec2(1999.5, 1499.5), axes);
  });
  std::printf("    stage: the layout networks and their box   %8.1f / %8.1f\n", layout.wallMs, layout.cpuMs);

  // detect --hint (issue 22 part 5) on the same 12 MP cluttered corridor: a person's rough
  // box (every corner 15 px of the 800x600 photo off, 75 px at 12 MP) fitted back. The fit
  // alone (hintWeighsDetection false: the editor's snap of one corner) is the baseline
  // for the fit weighed against detection's own answer (detect --hint, the editor's Fit
  // all corners), which runs the whole detection as well.
  const std::string clutterTruthPath = std::string(PW_GROUNDTRUTH_DIR) + "/clutter_1.json";
  const auto clutterTruth = pw::modeling::readShotFile(clutterTruthPath);
  if (!clutterTruth) {
    std::fprintf(stderr, "error: %s: %s\n", clutterTruthPath.c_str(), clutterTruth.message().c_str());
    return 1;
  }
  DetectOptions hintOptions = clutterOptions;
  hintOptions.hintPx = std::array<glm::dvec2, 8>{};
  hintOptions.hintReachPx = 25 * 5;
  for (int k = 0; k < 8; ++k) {
    const double angle = 0.9 + 1.7 * k;  // fixed directions, one per corner
    (*hintOptions.hintPx)[k] = 5.0 * (clutterTruth->cornersPx[k] + 15.0 * glm::dvec2(std::cos(angle), std::sin(angle))) + 2.0;
  }
  DetectOptions fitOnly = hintOptions;
  fitOnly.hintWeighsDetection = false;
  const Timing fitAlone = median(9, [&] { (void)detectCorridor(clutterBig, fitOnly); });
  std::printf("  baseline: detect --hint, the fit alone (snap) %8.1f / %8.1f\n", fitAlone.wallMs, fitAlone.cpuMs);
  const Timing hinted = median(9, [&] { (void)detectCorridor(clutterBig, hintOptions); });
  std::printf("  detect --hint, weighed with detection        %8.1f / %8.1f  (%+.1f / %+.1f against the fit alone)\n",
              hinted.wallMs, hinted.cpuMs, hinted.wallMs - fitAlone.wallMs, hinted.cpuMs - fitAlone.cpuMs);

  DetectOptions smallOptions;
  smallOptions.focalPx = kFocalSmall;
  const Timing smallRun = median(9, [&] { (void)detectCorridor(small, smallOptions); });
  std::printf("  detectCorridor, 800x600 corridor_a           %8.1f / %8.1f\n", smallRun.wallMs, smallRun.cpuMs);
  return found && clutterFound ? 0 : 1;
}
