// Frontal cross-sections of the corridor (the far wall, a band or frame across it):
// rectangles in 3D whose corners lie on the four receding boundaries and whose
// sides point at the horizontal and vertical vanishing points.
#pragma once

#include <array>
#include <optional>

#include <glm/glm.hpp>
#include <opencv2/core/types.hpp>

#include "base/result.h"
#include "metrology/detect/boundaries.h"
#include "metrology/detect/working_image.h"

namespace pw::metrology::detect {

// Corners in the shot's order: top-left, top-right, bottom-left, bottom-right (the
// far wall's P1 P2 P3 P4; the near section's P7 P8 P5 P6).
using Quad = std::array<glm::dvec2, 4>;
enum QuadSide : int { kTopSide = 0, kBottomSide, kLeftSide, kRightSide };
inline constexpr std::array<std::array<int, 2>, 4> kSideCorners{{{0, 1}, {2, 3}, {0, 2}, {1, 3}}};
// The two sides that meet at each corner: its top or bottom, then its left or right.
inline constexpr std::array<std::array<int, 2>, 4> kCornerSides{
    {{kTopSide, kLeftSide}, {kTopSide, kRightSide}, {kBottomSide, kLeftSide}, {kBottomSide, kRightSide}}};

// The one-parameter family of cross-sections: parameter t is the distance (working
// pixels) of the bottom-left corner from the vanishing point along the floor-left
// ray. For a box corridor, moving the cross-section in depth moves each corner
// along its boundary ray, and the image of one section maps to another by a planar
// homology with vertex at the vanishing point (Hartley & Zisserman, A7.2), so the
// section is fixed by t: bottom-right = floor-right ray ∩ (bottom-left, horizontal
// point), top-left = ceiling-left ray ∩ (bottom-left, vertical point), top-right
// from both top-left and bottom-right, averaged.
class CrossSectionFamily {
 public:
  // All in working pixels; horizontal and vertical are homogeneous (may be at infinity).
  CrossSectionFamily(glm::dvec2 vanishingPoint, glm::dvec3 horizontal, glm::dvec3 vertical,
                     const RecedingBoundaries& boundaries);
  std::optional<Quad> at(double t) const;
  // The largest t whose four corners stay `marginPx` inside an image of `size`.
  double largestInside(cv::Size size, double marginPx) const;
  glm::dvec2 vanishingPoint() const { return vp_; }
  glm::dvec3 horizontal() const { return horizontal_; }
  glm::dvec3 vertical() const { return vertical_; }

 private:
  glm::dvec2 vp_;
  glm::dvec3 horizontal_, vertical_;
  std::array<glm::dvec2, 4> rayDirection_{};  // per boundary
};

struct CrossSectionMatch {
  double t = 0;
  Quad corners{};
  std::array<double, 4> sideCoverage{};  // share of each side (top, bottom, left, right) on an image edge
  double boundaryContrast = 0;           // edge share along the rays just outside minus just inside
  double score = 0;
  // The side (0..3, as sideCoverage) taken as hidden: the section was scored on its
  // other three (findFarWall); -1 when all four show.
  int hiddenSide = -1;
};

// findFarWall's error where the four boundaries were found but no rectangle across the
// corridor where they begin: a room's box whose far wall does not show (detect.cpp takes
// the layout network's far wall as a guess there).
inline constexpr const char* kNoFarWallAcrossBoundaries = "no far wall: no rectangle across the corridor where its boundaries begin";

// The far wall: the section with edges on all four sides where the receding
// boundaries start (they run outwards from its corners, not inwards). A band or
// door frame nearer the camera has edges on its sides too, but the boundaries run
// on inside it. A section whose three best sides show clearly is scored on those
// three, less a penalty, with its fourth side hidden (hiddenSide): a person before a
// far corner, an open end's floor running on, a white wall under a white ceiling.
// The error says why none was found.
Result<CrossSectionMatch> findFarWall(const WorkingImage& image, const CrossSectionFamily& family);
// A far wall scored below this (down to findFarWall's least, 0.8) is found, but thinly:
// an answer through it is a guess (the random TUNE scenes 0-299: with 1.2 as the least,
// 3 more were "no corridor" with the box in view that 0.8 gets right, none lost).
inline constexpr double kClearFarWallScore = 1.2;

// The far wall where a person (roughly) put it: the best section within `reach` of
// t = `tCentre`, scored as findFarWall scores but over its three best-edged sides (one
// may be hidden), with no bar on the score; nullopt when no section there has edges on
// three sides.
std::optional<CrossSectionMatch> findFarWallNear(const WorkingImage& image, const CrossSectionFamily& family,
                                                 double tCentre, double reach);

// The far wall around the quad a person put (`rough`, working pixels, P1..P4), each of
// its sides free on its own: the side a line through its vanishing point (`horizontal`
// for top and bottom, `vertical` for the sides) within `reach` of where it was put, on
// one of the few best-edged lines there; the four chosen together so that the box's
// boundaries, the rays from `vp` through its corners, run on beyond the corners and not
// inside them (a pipe beside the far wall's corner is an edge too, but no boundary
// runs from it). Scored as findFarWall scores (three best sides), with a little more for
// the stronger steps and a little less for lines far from where the person put them;
// nullopt when a side shows no edge within reach. Each side is taken at the inner end
// of the lines with edges along it (a checkered floor keeps the edges going beyond the
// far wall's foot).
std::optional<CrossSectionMatch> fitFarWallNear(const WorkingImage& image, glm::dvec2 vp, glm::dvec3 horizontal,
                                                glm::dvec3 vertical, const Quad& rough, double reach);

// The t in [tFrom, tTo] whose section lies nearest (least squares over the corners)
// to the quad `q` (the same corner order and pixels as the family).
double nearestSection(const CrossSectionFamily& family, const Quad& q, double tFrom, double tTo);

// The nearest-to-the-far-wall section nearer the camera whose four sides all lie on
// image edges (a band, a frame, a beam across the corridor), if any.
std::optional<CrossSectionMatch> findMarkedCrossSection(const WorkingImage& image, const CrossSectionFamily& family,
                                                        double farWallT);

// The best-marked section within `reach` of t = `tCentre` (a doorway's frame or a band
// where a person put the near corners), if any.
std::optional<CrossSectionMatch> findMarkedCrossSectionNear(const WorkingImage& image, const CrossSectionFamily& family,
                                                            double tCentre, double reach);

}  // namespace pw::metrology::detect
