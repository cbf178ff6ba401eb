// A corridor's own frame and its surfaces (README, "Coordinate conventions"):
// right-handed, Y up, metres; floor at y = 0; the near end (the plane of P5..P8) at
// z = 0; the far wall at z = -length; x from -width/2 to +width/2. The camera that
// took the photo stands at some z > 0, and the photographed floor, walls and ceiling
// run on towards it: `nearM` says how far (z from 0 to nearM) a surface continues.
#pragma once

#include "metrology/measure.h"
#include "modeling/panel.h"

namespace pw::modeling {

enum class Surface : int { kFarWall = 0, kLeftWall, kRightWall, kFloor, kCeiling, kNearEnd };
inline constexpr int kSurfaceCount = 6;
const char* surfaceName(Surface surface);

// The panel of one surface, facing into the corridor, covering the box plus `nearM`
// beyond its near end (walls, floor, ceiling; the far wall and near end ignore it).
// (s, t) coordinates, the same whatever nearM is:
//   far wall   origin (-W/2, 0, -L)  s: +x  t: +y     s in [0, W]
//   left wall  origin (-W/2, 0, 0)   s: -z  t: +y     s in [-nearM, L]
//   right wall origin (+W/2, 0, -L)  s: +z  t: +y     s in [0, L + nearM]
//   floor      origin (-W/2, 0, 0)   s: +x  t: -z     t in [-nearM, L]
//   ceiling    origin (-W/2, H, -L)  s: +x  t: +z     t in [0, L + nearM]
//   near end   origin (+W/2, 0, 0)   s: -x  t: +y     s in [0, W]   (faces -z)
// `box`: the corridor's measured width, height and length.
Panel surfacePanel(Surface surface, const metrology::Dimensions& box, double nearM = 0.0);

}  // namespace pw::modeling
