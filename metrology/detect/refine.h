// Full-resolution refinement of the coarse structure found on the working copy.
#pragma once

#include <array>
#include <optional>

#include <glm/glm.hpp>
#include <opencv2/core/mat.hpp>

#include "metrology/detect/boundaries.h"
#include "metrology/detect/cross_sections.h"
#include "metrology/detect/edge_fit.h"

namespace pw::metrology::detect {

struct RefinedSection {
  Quad corners{};                       // full-resolution pixels, order of Quad
  std::array<EdgeLine, 4> sides{};      // top, bottom, left, right
  std::array<bool, 4> sideFitted{};     // false: the coarse side was kept (no edge found)
  std::array<double, 4> cornerConfidence{};
  std::array<double, 4> cornerSigmaPx{};
};

// Refits each side of a cross-section (coarse corners in full-resolution pixels) to
// the image edge within `searchPx`, keeping top and bottom through the horizontal
// vanishing point and left and right through the vertical one, and intersects them.
// A side with no edge keeps its coarse line and gives its corners low confidence.
// `minRelativeStrength` as in EdgeSearch.
//
// `innerPoint` (the vanishing point): the top and bottom take the edge farthest towards
// it (EdgeSearch::innerPoint). A far wall's foot borders the floor, whose tile joints run
// parallel to it a pixel or three away; its sides border the walls, where clutter and
// doorways make inner edges of their own, so they keep the edge nearest the coarse line.
RefinedSection refineCrossSection(const PinholeView& photo, const Quad& coarse, glm::dvec3 horizontal,
                                  glm::dvec3 vertical, double searchPx, double stepHalfWidthPx,
                                  double minRelativeStrength = 0.5, std::optional<glm::dvec2> innerPoint = {});

struct RefinedBoundary {
  glm::dvec2 direction{1, 0};  // unit, from the vanishing point outwards
  std::optional<EdgeLine> fit;
};

// Refits each boundary ray through the vanishing point (full-resolution pixels) to
// the image edge beyond radius `fromRadius[b]`, to the image border. The search
// window widens with the radius, as the coarse angle's error does.
std::array<RefinedBoundary, kBoundaryCount> refineBoundaries(const PinholeView& photo, glm::dvec2 vanishingPoint,
                                                             const std::array<glm::dvec2, kBoundaryCount>& coarseDirection,
                                                             const std::array<double, kBoundaryCount>& fromRadius,
                                                             double searchPx, double stepHalfWidthPx);
// (searchPx applies at the inner end; the window grows by 0.3 degree's worth of
// radius towards the border.)

}  // namespace pw::metrology::detect
