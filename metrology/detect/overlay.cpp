#include "metrology/detect/overlay.h"

#include <algorithm>
#include <cstdio>

#include <opencv2/imgproc.hpp>

#include "metrology/shot.h"

namespace pw::metrology::detect {

cv::Mat drawDetection(const cv::Mat& photo, const CorridorDetection& d) {
  cv::Mat out = photo.clone();
  if (!d.found) return out;
  const double unit = std::max(1.0, std::max(photo.cols, photo.rows) / 800.0);
  const int thin = std::max(1, static_cast<int>(unit)), thick = std::max(2, static_cast<int>(2 * unit));
  const auto pt = [](glm::dvec2 p) { return cv::Point(static_cast<int>(std::lround(p.x * 16)), static_cast<int>(std::lround(p.y * 16))); };
  const auto line = [&](glm::dvec2 a, glm::dvec2 b, cv::Scalar colour, int width) {
    cv::line(out, pt(a), pt(b), colour, width, cv::LINE_AA, 4);
  };
  const auto& c = d.corners;
  const cv::Scalar cyan(255, 255, 0), magenta(255, 0, 255), yellow(0, 255, 255);
  // Receding boundaries: far corner to near corner, continued to the vanishing point.
  const glm::dvec2 vp = d.corridor.pixel();
  for (auto [far, near] : {std::pair{P1, P7}, {P2, P8}, {P3, P5}, {P4, P6}}) {
    line(vp, c[far].px, yellow, thin);
    line(c[far].px, c[near].px, cyan, thick);
  }
  for (auto [a, b] : {std::pair{P1, P2}, {P3, P4}, {P1, P3}, {P2, P4}}) line(c[a].px, c[b].px, magenta, thick);
  for (auto [a, b] : {std::pair{P7, P8}, {P5, P6}, {P7, P5}, {P8, P6}}) line(c[a].px, c[b].px, cyan, thin);
  cv::drawMarker(out, cv::Point(static_cast<int>(vp.x), static_cast<int>(vp.y)), yellow, cv::MARKER_CROSS,
                 static_cast<int>(12 * unit), thin);
  for (int k = 0; k < kCornerCount; ++k) {
    const double conf = c[k].confidence;
    const cv::Scalar ring = conf >= 0.7 ? cv::Scalar(0, 200, 0) : conf >= 0.4 ? cv::Scalar(0, 170, 255) : cv::Scalar(0, 0, 255);
    cv::circle(out, pt(c[k].px), static_cast<int>(6 * unit * 16), ring, thick, cv::LINE_AA, 4);
    char label[32];
    std::snprintf(label, sizeof label, "%s %.2f", cornerName(k), conf);
    const cv::Point at(static_cast<int>(c[k].px.x + 8 * unit), static_cast<int>(c[k].px.y - 8 * unit));
    cv::putText(out, label, at, cv::FONT_HERSHEY_SIMPLEX, 0.45 * unit, cv::Scalar(0, 0, 0), thick + 1, cv::LINE_AA);
    cv::putText(out, label, at, cv::FONT_HERSHEY_SIMPLEX, 0.45 * unit, ring, thin, cv::LINE_AA);
  }
  return out;
}

}  // namespace pw::metrology::detect
