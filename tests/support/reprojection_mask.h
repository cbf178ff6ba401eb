// Comparing a frame rendered from a photo's camera with the photo: where to look and
// how to score it (tests/pipeline: reprojection, render --camera-from).
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include <glm/glm.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "metrology/shot.h"

namespace pw::test {

// The pixels of a `size` frame inside the quad P5-P6-P8-P7 (what the box between the
// near corners and the far wall covers), 255 in, 0 out, leaving out `edgeMarginPx`
// pixels on each side of every plane edge (where a photo pixel mixes two planes);
// 0 keeps the edges. Corners in pixels (OpenCV convention), drawn at 1/16 px so that
// the mask follows the corners, not their rounding.
inline cv::Mat corridorMask(const std::array<glm::dvec2, metrology::kCornerCount>& cornersPx, cv::Size size,
                            int edgeMarginPx) {
  using namespace metrology;
  const auto fine = [&](int corner) {
    return cv::Point(cvRound(cornersPx[corner].x * 16), cvRound(cornersPx[corner].y * 16));
  };
  cv::Mat mask = cv::Mat::zeros(size, CV_8U);
  const std::vector<cv::Point> quad = {fine(P5), fine(P6), fine(P8), fine(P7)};
  cv::fillConvexPoly(mask, quad, 255, cv::LINE_8, 4);
  if (edgeMarginPx <= 0) return mask;
  const int edges[][2] = {{P1, P2}, {P2, P4}, {P4, P3}, {P3, P1}, {P7, P1}, {P8, P2},
                          {P5, P3}, {P6, P4}, {P5, P6}, {P6, P8}, {P8, P7}, {P7, P5}};
  for (const auto& e : edges) cv::line(mask, fine(e[0]), fine(e[1]), 0, 2 * edgeMarginPx + 1, cv::LINE_8, 4);
  return mask;
}

// PSNR in dB of two 8-bit frames of the same size and type over the mask's non-zero
// pixels (all channels); 99 when they are equal there.
inline double maskedPsnr(const cv::Mat& a, const cv::Mat& b, const cv::Mat& mask) {
  cv::Mat diff;
  cv::absdiff(a, b, diff);
  diff.convertTo(diff, CV_64FC(a.channels()));
  diff = diff.mul(diff);
  diff.setTo(cv::Scalar::all(0), ~mask);
  const cv::Scalar sum = cv::sum(diff);
  const double n = double(a.channels()) * cv::countNonZero(mask);
  const double mse = (sum[0] + sum[1] + sum[2] + sum[3]) / n;
  return mse > 0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : 99.0;
}

}  // namespace pw::test
