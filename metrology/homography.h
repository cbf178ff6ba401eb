// Plane homographies from four point correspondences (the seed paper's section 2.2).
#pragma once

#include <array>

#include <glm/glm.hpp>
#include <opencv2/core/matx.hpp>

#include "base/result.h"

namespace pw::metrology {

// The homography H (h33 = 1) with dst_i ~ H · src_i for four correspondences, from
// the seed paper's 8x8 linear system A·T = B (its equations 1-4), solved after
// Hartley normalisation of both point sets for conditioning. Fails when three of
// either set's points are collinear (A is singular).
Result<cv::Matx33d> homographyFromCorners(const std::array<glm::dvec2, 4>& src, const std::array<glm::dvec2, 4>& dst);

// H applied to a point (with the perspective division).
glm::dvec2 applyHomography(const cv::Matx33d& h, const glm::dvec2& p);

// The 2x2 Jacobian of the map p -> H·p at p: how far the image moves per unit step
// in x (column 0) and in y (column 1).
glm::dmat2 homographyJacobian(const cv::Matx33d& h, const glm::dvec2& p);

// Largest singular value of a 2x2 matrix: the most a unit step can be stretched.
double largestStretch(const glm::dmat2& j);

}  // namespace pw::metrology
