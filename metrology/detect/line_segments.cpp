#include "metrology/detect/line_segments.h"

#include <cmath>

#include <opencv2/imgproc.hpp>

namespace pw::metrology::detect {

std::vector<LineSegment> detectLineSegments(const cv::Mat& gray, double scale, double minLengthPx) {
  // LSD's Gaussian down-sampling by 0.8 (the paper's default, against aliasing and
  // staircase edges) returns u_scaled / 0.8, which is off the pixel-centre mapping
  // (u_scaled + 0.5) / 0.8 - 0.5 by a constant 0.125 px; that is added back here.
  constexpr double kLsdScale = 0.8;
  constexpr double kLsdOffset = 0.5 / kLsdScale - 0.5;
  cv::Ptr<cv::LineSegmentDetector> lsd = cv::createLineSegmentDetector(cv::LSD_REFINE_STD, kLsdScale);
  std::vector<cv::Vec4f> raw;
  lsd->detect(gray, raw);
  std::vector<LineSegment> segments;
  segments.reserve(raw.size());
  const auto toFull = [scale](double x) { return (x + kLsdOffset + 0.5) / scale - 0.5; };
  for (const cv::Vec4f& r : raw) {
    LineSegment s;
    s.a = glm::dvec2(toFull(r[0]), toFull(r[1]));
    s.b = glm::dvec2(toFull(r[2]), toFull(r[3]));
    s.lengthPx = glm::length(s.b - s.a);
    if (s.lengthPx >= minLengthPx && std::isfinite(s.lengthPx)) segments.push_back(s);
  }
  return segments;
}

}  // namespace pw::metrology::detect
