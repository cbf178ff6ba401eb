// A camera tour through a corridor or a building: walk along each corridor's centre
// line at eye height, turn into side corridors, turn round at dead ends, and come back.
// Smooth: corners are rounded with arcs, turns on the spot ease in and out, and the
// walk runs at a steady speed.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "modeling/layout.h"
#include "engine/scene/camera.h"

namespace pw::modeling {

struct TourOptions {
  double eyeHeightM = 1.6;
  double walkSpeedMps = 1.2;
  double turnSpeedDegPerS = 90.0;
  double wallMarginM = 1.0;   // stop this far before a dead-end wall
  double cornerRadiusM = 0.8;
  double startZ = 0.0;        // where the walk starts in the first corridor (its frame)
};

// The walk as a polyline in world space (before rounding), from `startZ` in the
// first corridor through every corridor reachable by attachments, back to the start.
std::vector<glm::dvec3> tourWaypoints(const Layout& layout, const std::vector<metrology::Dimensions>& boxes,
                                      const BuildingPlan& plan, const TourOptions& options);

// A position and heading at any time of the walk along `waypoints`.
class TourPath {
 public:
  TourPath(const std::vector<glm::dvec3>& waypoints, const TourOptions& options);
  double durationS() const { return duration_; }
  // Eye position and heading (yaw about +Y, radians; 0 looks along -Z) at time t.
  void sample(double t, glm::dvec3& position, double& yawRad) const;
  // `frames` cameras spread evenly over the whole walk (first at t = 0, last at the end).
  std::vector<engine::Camera> cameras(int frames, float fieldOfViewRad) const;

 private:
  struct Piece {
    enum Kind { kLine, kArc, kTurn } kind;
    glm::dvec3 a, control, b;  // line a-b; quadratic Bezier a-control-b; turn at a
    double yaw0 = 0, yaw1 = 0;  // turn: from, to
    double duration = 0;
  };
  std::vector<Piece> pieces_;
  double duration_ = 0;
};

double yawOf(const glm::dvec3& direction);  // 0 for -Z, +pi/2 for -X (turning left)

}  // namespace pw::modeling
