// Vanishing geometry of a corridor: where its receding, horizontal and vertical
// edges meet in the image, and the horizon.
//
// Image coordinates are pixels with v down (see shot.h). Lines are homogeneous
// (a, b, c) with a·u + b·v + c = 0 and (a, b) of unit length, so that line · (u, v, 1)
// is the signed distance of a pixel from the line.
#pragma once

#include <array>
#include <span>

#include <glm/glm.hpp>

#include "base/result.h"
#include "metrology/shot.h"

namespace pw::metrology {

using ImageLine = glm::dvec3;

// The line through two distinct pixels, normalised as above. Returns an error when
// they coincide (closer than 1e-9 px).
Result<ImageLine> lineThrough(const glm::dvec2& a, const glm::dvec2& b);

// Signed distance in pixels of `p` from a normalised line.
inline double signedDistancePx(const ImageLine& line, const glm::dvec2& p) { return line.x * p.x + line.y * p.y + line.z; }

// An image segment, oriented: `from` -> `to` points the way the 3D edge runs.
struct Segment {
  glm::dvec2 from{0.0};
  glm::dvec2 to{0.0};
};

// Where several image lines meet. Lines that are parallel in the image (the 3D
// direction is parallel to the image plane) meet at infinity: a normal case, given
// as a direction instead of a position.
struct VanishingPoint {
  glm::dvec3 homogeneous{0.0, 0.0, 1.0};  // unit length; third component 0 at infinity
  bool finite = true;
  glm::dvec2 px{0.0};         // the meeting point, when finite
  glm::dvec2 direction{0.0};  // unit image direction of the lines, when at infinity
  // How well the lines agree: RMS distance (px) of the segments' endpoints from the
  // lines through each segment's midpoint and the vanishing point (Rother's
  // consistency measure). 0 for lines that meet exactly.
  double residualPx = 0;
};

// Least-squares meet of the segments' lines: the homogeneous point x minimising
// Σ (l_i · x)² over |x| = 1 after Hartley normalisation of the coordinates. For a
// finite point that is the least-squares sum of squared point-to-line distances; for
// (nearly) parallel lines the minimiser goes to infinity smoothly instead of
// blowing up. A point farther than 1e6 times the segments' spread counts as at
// infinity. Needs at least two segments of non-zero length.
Result<VanishingPoint> fitVanishingPoint(std::span<const Segment> segments);

// The corridor's three families of parallel edges (METHOD.md, "The constructions";
// Hartley & Zisserman 8.6).
struct CorridorVanishing {
  VanishingPoint corridor;    // receding edges, near to far: P7-P1, P8-P2, P5-P3, P6-P4
  VanishingPoint horizontal;  // left to right: P1-P2, P3-P4, P5-P6, P7-P8
  VanishingPoint vertical;    // bottom to top: P3-P1, P4-P2, P5-P7, P6-P8
  // The floor's vanishing line, through the corridor and horizontal vanishing points,
  // signed so that floor corners have positive distance (they lie below it).
  ImageLine horizon{0.0, 1.0, 0.0};
  // Angle of the horizon from the image u axis, degrees, positive when it falls to
  // the right (v grows): the camera's roll (see corridor_frame.h for the sign).
  double rollDeg = 0;
};

// Fits the three vanishing points and the horizon from the eight corners. Fails
// (with a message naming the corners) when an edge has zero length or the corridor
// direction meets at infinity or behind the camera.
Result<CorridorVanishing> corridorVanishing(const std::array<glm::dvec2, kCornerCount>& cornersPx);

}  // namespace pw::metrology
