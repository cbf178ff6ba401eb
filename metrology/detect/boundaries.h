// The corridor's four receding boundaries (floor-wall and ceiling-wall edges): rays
// from the corridor vanishing point.
#pragma once

#include <array>
#include <optional>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "base/result.h"
#include "metrology/detect/working_image.h"

namespace pw::metrology::detect {

enum Boundary : int { kFloorLeft = 0, kFloorRight, kCeilingLeft, kCeilingRight };
inline constexpr int kBoundaryCount = 4;
const char* boundaryName(int boundary);

// A boundary must follow an edge over a quarter of its outer half at least (people or
// furniture may hide the rest; RecedingBoundaries::edgeCoverage).
inline constexpr double kMinBoundaryEdgeCoverage = 0.25;

struct RecedingBoundaries {
  // Angle of each ray from the vanishing point, radians, in the image frame (0 along
  // +u, pi/2 along +v, i.e. downwards), at working resolution.
  std::array<double, kBoundaryCount> angle{};
  // How different the two sides look (colour and texture), in units of the photo's
  // own variation across all angles: > ~1.5 is a clear boundary.
  std::array<double, kBoundaryCount> contrast{};
  // Share of the ray's outer half where an edge runs along it.
  std::array<double, kBoundaryCount> edgeCoverage{};
  // The boundary taken where the other three put it (impliedBoundaryAngle): its quadrant
  // shows no step, or no edge runs along it (the only one under kMinBoundaryEdgeCoverage);
  // -1 where all four were found.
  int implied = -1;
  // Taken at the outer edge of a band along the walls (a skirting board's foot).
  std::array<bool, kBoundaryCount> belowBand{};
  // The other sets of each quadrant's few strongest steps that make a box, heaviest
  // first (findRecedingBoundaries; only where all four were found): a person's outline
  // or a side opening's edge can make the set taken a wrong box and the true one a
  // lighter one. Each with at least kAlternativeWeightShare of the set taken's
  // summed weight (each step's strength, times its ray's edge coverage where that is
  // under half) and an edge along each of its four rays.
  std::vector<RecedingBoundaries> alternatives;

  glm::dvec2 direction(int boundary) const { return {std::cos(angle[boundary]), std::sin(angle[boundary])}; }
};

// Outside the far wall, a corridor photo is four angular sectors around the vanishing
// point (floor, two walls, ceiling), and every ray from the point stays in one plane.
// So the mean colour and texture along each ray (the "angular profile", texture
// averaging out along the ray) is piecewise constant with four steps. In each quadrant
// (measured from the horizon) the few strongest steps are placed on the sharpest colour
// step near them, and the boundary is the heaviest: its strength, times its ray's edge
// coverage where an edge runs along less than half of it (a junction of two surfaces is
// an edge all along, a row of lamps or a wall's shading is not).
// `vanishingPoint` is in working pixels; `horizonAngle` is the direction of the
// horizon (towards the horizontal vanishing point) in radians, pointing right.
// With the horizontal and vertical points (`sectionPoints`, homogeneous, working pixels),
// the four are taken together: a box's cross-section is a rectangle whose top and bottom
// point at the one and sides at the other, so any three boundaries fix the fourth, and
// where the steps taken disagree with that (a lamp row along the ceiling passing for
// its edge with a wall), the heaviest set among each quadrant's few strongest steps
// that agrees is taken; and one boundary that does not show (no step in its quadrant,
// or the only one with no edge along it) is where the other three put it (`implied`).
Result<RecedingBoundaries> findRecedingBoundaries(const WorkingImage& image, glm::dvec2 vanishingPoint,
                                                  double horizonAngle,
                                                  std::optional<std::pair<glm::dvec3, glm::dvec3>> sectionPoints = {});

// The direction (radians) of boundary `missing` that the other three of `rays` imply,
// through a cross-section whose top and bottom point at `horizontal` and whose sides
// point at `vertical` (homogeneous; all in working pixels); nullopt where the lines
// do not cross.
std::optional<double> impliedBoundaryAngle(const RecedingBoundaries& rays, int missing, glm::dvec2 vanishingPoint,
                                           glm::dvec3 horizontal, glm::dvec3 vertical);

// Share of the ray from `vp` at `angle` (working pixels, radians) whose outer half
// runs along an image edge.
double rayEdgeCoverage(const WorkingImage& image, glm::dvec2 vp, double angle);

// The boundaries near the angles a person gave (radians, one per boundary): in each,
// the strongest step of the angular profile within `reachRad` of it, placed by the
// sharpest colour step near that, as findRecedingBoundaries places them (a tile joint
// along the floor is an edge but no step: the floor's colour on both sides). Where no
// step stands out, the angle given. With `horizonAngle` (radians, the horizon's direction
// from the vanishing point), a floor boundary found on a band along the walls, a skirting
// board's top, is taken at the band's foot (RecedingBoundaries::belowBand).
RecedingBoundaries boundariesNear(const WorkingImage& image, glm::dvec2 vanishingPoint,
                                  const std::array<double, kBoundaryCount>& angle,
                                  const std::array<double, kBoundaryCount>& reachRad,
                                  std::optional<double> horizonAngle = std::nullopt);

// Distance from `origin` along the unit `direction` to the image border (working pixels).
double distanceToBorder(const WorkingImage& image, glm::dvec2 origin, glm::dvec2 direction);

}  // namespace pw::metrology::detect
