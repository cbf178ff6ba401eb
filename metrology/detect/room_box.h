// The far wall found from the corridor's box as one model (issue 15), for photos where
// clutter hides the floor-wall boundaries and the angular profile cannot place them.
#pragma once

#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "base/result.h"
#include "metrology/detect/cross_sections.h"
#include "metrology/detect/line_segments.h"
#include "metrology/detect/working_image.h"

namespace pw::metrology::detect {

struct RoomBox {
  Quad corners{};                        // the far wall, working pixels, order of Quad
  std::array<double, 4> sideCoverage{};  // top, bottom, left, right: share on an edge
  // Per boundary (floor-left, floor-right, ceiling-left, ceiling-right): share of
  // the ray from the vanishing point through the far corner on an edge beyond the
  // corner (to the photo's border) and before it (over the far wall, where a box
  // corridor has no boundary).
  std::array<double, 4> rayOutside{};
  std::array<double, 4> rayInside{};
  double score = 0;
  // The next best boxes (up to five, best first), no two with all four sides within 3 px
  // of each other on the rectified photo: a person before a far corner, or a bench along
  // the foot, can make a nearer rectangle of clutter's edges score best.
  std::vector<RoomBox> alternatives;
};

// Every far-wall rectangle of a box corridor has its top and bottom through the
// horizontal vanishing point, its sides through the vertical one, and contains the
// corridor's vanishing point; the four boundaries run from that point through its
// corners. In the photo mapped by the homography that sends the horizontal and
// vertical points to infinity (and keeps the scale at the corridor's vanishing
// point), those rectangles are axis-aligned and the boundaries are rays from the
// origin, whatever the camera's roll. Candidate sides come from the straight
// segments (labelled by the Manhattan frame: 1 horizontal, 2 vertical) and from the
// edge profile just above the vanishing point (above most clutter); each
// combination is scored by the edge support of its four sides and of its four
// boundaries along their whole length beyond the corners, less the support the rays
// have over the far wall (a band or door frame nearer the camera has the boundaries
// running on through it). Works on the working copy; `segments` and `labels` are the
// full-resolution segments and their frame labels. The error says why no box fits.
Result<RoomBox> fitRoomBox(const WorkingImage& image, glm::dvec2 vanishingPoint, glm::dvec3 horizontal,
                           glm::dvec3 vertical, const std::vector<LineSegment>& segments, const std::vector<int>& labels);

}  // namespace pw::metrology::detect
