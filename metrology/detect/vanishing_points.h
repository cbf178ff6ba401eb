// The Manhattan frame of a corridor photo: three mutually orthogonal directions
// (along the corridor, across it, vertical) and their vanishing points.
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>
#include <opencv2/core/types.hpp>

#include "base/result.h"
#include "metrology/detect/line_segments.h"

namespace pw::metrology::detect {

struct PinholeCamera {
  double focalPx = 0;
  glm::dvec2 principalPointPx{0, 0};
};

struct VanishingPoint {
  glm::dvec3 point{0, 0, 1};  // homogeneous image point, unit length; z == 0 at infinity
  int inlierCount = 0;
  double inlierLengthPx = 0;  // summed length of the segments that point at it
  double rmsAngleDeg = 0;     // RMS angle between inlier segments and the lines to the point
  double confidence = 0;      // 0..1, see estimateManhattanFrame
  bool isFinite() const { return std::abs(point.z) > 1e-9; }
  glm::dvec2 pixel() const { return {point.x / point.z, point.y / point.z}; }
};

struct ManhattanFrame {
  VanishingPoint corridor;    // the finite one the corridor recedes to
  VanishingPoint horizontal;  // across the corridor (usually near infinity)
  VanishingPoint vertical;
  std::vector<int> labels;    // per input segment: 0 corridor, 1 horizontal, 2 vertical, -1 none
};

// Finds three orthogonal directions by RANSAC over the segments' interpretation
// planes on the Gaussian sphere (Barnard 1983; the 2-line + 1-line minimal sample of
// Wildenauer & Hanbury, "Robust camera self-calibration from monocular images of
// Manhattan worlds", CVPR 2012): two segments give one direction, a third segment
// gives the second orthogonal to it, the cross product the third. Each direction is
// then refined by weighted least squares over its inliers, independently, so a wrong
// focal length biases the classification only, not the vanishing points. The
// corridor direction is the one most nearly along the optical axis.
//
// Confidence: corridor = (share of 8 angular sectors around the point that hold
// inlier segments) x (1 - exp(-inlier length / image diagonal)); horizontal and
// vertical = 1 - exp(-2 inlier length / image diagonal). The error says why no
// frame was found (too few segments, no finite corridor point).
Result<ManhattanFrame> estimateManhattanFrame(const std::vector<LineSegment>& segments, const PinholeCamera& camera,
                                              cv::Size imageSize);

// Refines a finite vanishing point in the image by Gauss-Newton on the distance of
// each member segment's end points from the line joining its midpoint to the point
// (the usual maximum-likelihood approximation, e.g. Tardif, ICCV 2009, eq. 2),
// weighted by segment length: unlike the fit on the Gaussian sphere, it does not
// depend on the focal length.
glm::dvec2 refineFinitePoint(glm::dvec2 point, const std::vector<LineSegment>& segments, const std::vector<int>& members);

// Focal length from two finite vanishing points of orthogonal directions:
// f^2 = -(v1 - c)·(v2 - c) with c the principal point (Hartley & Zisserman, 8.8.1).
// nullopt when either point is at (or near) infinity or the product is not negative.
std::optional<double> focalFromOrthogonalPoints(const VanishingPoint& v1, const VanishingPoint& v2,
                                                glm::dvec2 principalPointPx, double imageDiagonalPx);

}  // namespace pw::metrology::detect
