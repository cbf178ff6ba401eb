#include "metrology/detect/line_segments.h"

#include <algorithm>
#include <cmath>

#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>

namespace pw::metrology::detect {

std::vector<LineSegment> detectLineSegments(const cv::Mat& gray, double scale, double minLengthPx) {
  // LSD's Gaussian down-sampling by 0.8 (the paper's default, against aliasing and
  // staircase edges) returns u_scaled / 0.8, which is off the pixel-centre mapping
  // (u_scaled + 0.5) / 0.8 - 0.5 by a constant 0.125 px; that is added back here.
  constexpr double kLsdScale = 0.8;
  constexpr double kLsdOffset = 0.5 / kLsdScale - 0.5;
  // LSD is sequential; the photo is cut into horizontal bands run in parallel (two
  // cores: two bands). A segment crossing a cut comes back as two pieces on the same
  // line, which is all the vanishing-point fit needs.
  const int bands = gray.rows >= 400 ? std::max(1, std::min(cv::getNumThreads(), 4)) : 1;
  std::vector<std::vector<cv::Vec4f>> raw(bands);
  cv::parallel_for_(cv::Range(0, bands), [&](const cv::Range& range) {
    for (int band = range.start; band < range.end; ++band) {
      const int y0 = gray.rows * band / bands, y1 = gray.rows * (band + 1) / bands;
      cv::Ptr<cv::LineSegmentDetector> lsd = cv::createLineSegmentDetector(cv::LSD_REFINE_STD, kLsdScale);
      lsd->detect(gray(cv::Range(y0, y1), cv::Range::all()), raw[band]);
      // LSD's coordinates are relative to the band; the offset is exact in pixels of
      // the working copy, so it is added after LSD's own 0.8 mapping.
      for (cv::Vec4f& r : raw[band]) r[1] += static_cast<float>(y0), r[3] += static_cast<float>(y0);
    }
  });
  std::vector<LineSegment> segments;
  const auto toFull = [scale](double x) { return (x + kLsdOffset + 0.5) / scale - 0.5; };
  for (const auto& band : raw) {
    for (const cv::Vec4f& r : band) {
      LineSegment s;
      s.a = glm::dvec2(toFull(r[0]), toFull(r[1]));
      s.b = glm::dvec2(toFull(r[2]), toFull(r[3]));
      s.lengthPx = glm::length(s.b - s.a);
      if (s.lengthPx >= minLengthPx && std::isfinite(s.lengthPx)) segments.push_back(s);
    }
  }
  return segments;
}

}  // namespace pw::metrology::detect
