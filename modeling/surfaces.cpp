#include "modeling/surfaces.h"

namespace pw::modeling {

const char* surfaceName(Surface surface) {
  static const char* const kNames[kSurfaceCount] = {"far_wall", "left_wall", "right_wall", "floor", "ceiling", "near_end"};
  return kNames[static_cast<int>(surface)];
}

Panel surfacePanel(Surface surface, const metrology::Dimensions& box, double nearM) {
  const double w = box.widthM, h = box.heightM, l = box.lengthM;
  Panel p;
  switch (surface) {
    case Surface::kFarWall:
      p.origin = {-w / 2, 0, -l};
      p.sAxis = {1, 0, 0};
      p.tAxis = {0, 1, 0};
      p.extent = {0, 0, w, h};
      break;
    case Surface::kLeftWall:
      p.origin = {-w / 2, 0, 0};
      p.sAxis = {0, 0, -1};
      p.tAxis = {0, 1, 0};
      p.extent = {-nearM, 0, l, h};
      break;
    case Surface::kRightWall:
      p.origin = {w / 2, 0, -l};
      p.sAxis = {0, 0, 1};
      p.tAxis = {0, 1, 0};
      p.extent = {0, 0, l + nearM, h};
      break;
    case Surface::kFloor:
      p.origin = {-w / 2, 0, 0};
      p.sAxis = {1, 0, 0};
      p.tAxis = {0, 0, -1};
      p.extent = {0, -nearM, w, l};
      break;
    case Surface::kCeiling:
      p.origin = {-w / 2, h, -l};
      p.sAxis = {1, 0, 0};
      p.tAxis = {0, 0, 1};
      p.extent = {0, 0, w, l + nearM};
      break;
    case Surface::kNearEnd:
      p.origin = {w / 2, 0, 0};
      p.sAxis = {-1, 0, 0};
      p.tAxis = {0, 1, 0};
      p.extent = {0, 0, w, h};
      break;
  }
  return p;
}

}  // namespace pw::modeling
