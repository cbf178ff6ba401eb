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
  double rmsAngleDeg = 0;     // RMS angle between inlier segments and the lines to the point,
                              // over those away from it (see estimateManhattanFrame's .cpp)
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

// How the three directions are refined once the frame is found.
enum class FrameRefinement {
  // The focal length is known: one rotation is also fitted to all three families of
  // segments at once (orthogonal directions), and a direction whose own fit strays
  // from it by more than a quarter of a degree (a weak or contaminated family) is
  // replaced by the rotation's, fixed by the other two; the others keep their own fit,
  // which a principal point slightly off does not bias.
  kJointOrthogonal,
  // The focal length is a guess: each direction fitted alone (and the corridor's point
  // refined in the image, refineFinitePoint), so that the guess biases the labels only,
  // not the vanishing points, and a focal length can be read off two of them.
  kIndependent,
};

// Finds three orthogonal directions on the Gaussian sphere (Barnard 1983), each
// segment a great circle (its interpretation plane). Hypotheses: the first direction
// from two segments drawn at random, the second searched exhaustively around the great
// circle orthogonal to it (the 2-line exhaustive search of Lu et al., WACV 2017, here
// on a 0.25° histogram of where each segment's plane crosses that circle), the third
// their cross product; each scored by the 400 longest segments, a segment counting once
// for the direction its plane passes nearest, within 1.5°. The best is refined as `refinement`
// says (each direction by least squares over its segments within 1.5°, the rotation
// over those within 1°; the corridor's point then in the image, refineFinitePoint,
// unless the rotation replaced it). The corridor direction is the one most nearly along the optical axis.
//
// Confidence: corridor = (share of 8 angular sectors around the point that hold
// inlier segments) x (1 - exp(-inlier length / image diagonal)); horizontal and
// vertical = 1 - exp(-2 inlier length / image diagonal). The error says why no
// frame was found (too few segments, no finite corridor point).
Result<ManhattanFrame> estimateManhattanFrame(const std::vector<LineSegment>& segments, const PinholeCamera& camera,
                                              cv::Size imageSize,
                                              FrameRefinement refinement = FrameRefinement::kJointOrthogonal);

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
