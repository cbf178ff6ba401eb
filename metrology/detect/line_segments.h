// Straight line segments of a photo, at sub-pixel precision.
#pragma once

#include <vector>

#include <glm/glm.hpp>
#include <opencv2/core/mat.hpp>

namespace pw::metrology::detect {

struct LineSegment {
  glm::dvec2 a, b;  // end points, full-resolution pixels
  double lengthPx = 0;
};

// Runs OpenCV's line segment detector (von Gioi et al., "LSD: a fast line segment
// detector with a false detection control", IPOL 2012) on `gray` (8-bit, one
// channel), which is the photo scaled by `scale` (<= 1). End points are mapped back
// to full-resolution pixel centres: u = (u_scaled + 0.5) / scale - 0.5. Segments
// shorter than `minLengthPx` (full resolution) are dropped. LSD's a-contrario test
// keeps noise from producing segments, so a blank or noisy photo yields few or none.
// Runs in horizontal bands on OpenCV's threads (a segment crossing a band's edge
// comes back in two pieces).
std::vector<LineSegment> detectLineSegments(const cv::Mat& gray, double scale, double minLengthPx);

}  // namespace pw::metrology::detect
