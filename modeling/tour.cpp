#include "modeling/tour.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>

namespace pw::modeling {
namespace {

glm::dvec3 apply(const glm::dmat4& m, const glm::dvec3& p) { return glm::dvec3(m * glm::dvec4(p, 1.0)); }

double wrapAngle(double a) {
  while (a > glm::pi<double>()) a -= glm::two_pi<double>();
  while (a < -glm::pi<double>()) a += glm::two_pi<double>();
  return a;
}

double smoothstep(double x) { return x * x * (3.0 - 2.0 * x); }

struct Walker {
  const Layout& layout;
  const std::vector<metrology::Dimensions>& boxes;
  const BuildingPlan& plan;
  const TourOptions& options;
  std::vector<glm::dvec3> points;

  glm::dvec3 at(int corridor, double z) const {
    return apply(plan.worldFromCorridor[corridor], {0.0, options.eyeHeightM, z});
  }

  // Walks corridor c from its entry at z = entryZ to its end and back to the entry.
  void walk(int c, double entryZ) {
    const double length = boxes[c].lengthM;
    const double deadEnd = -std::max(0.0, length - options.wallMarginM);
    struct Branch {
      int corridor;
      double depth;  // distance from c's near end along its axis
    };
    std::vector<Branch> sides;
    int farChild = -1;
    for (size_t i = 0; i < layout.corridors.size(); ++i) {
      const auto& attach = layout.corridors[i].attach;
      if (!attach || attach->to != c) continue;
      if (attach->side == Side::kFar) {
        if (farChild < 0) farChild = static_cast<int>(i);
      } else {
        sides.push_back({static_cast<int>(i), attach->offsetM});
      }
    }
    std::sort(sides.begin(), sides.end(), [](const Branch& x, const Branch& y) { return x.depth < y.depth; });
    points.push_back(at(c, entryZ));
    for (const Branch& side : sides) {
      if (-side.depth > entryZ) continue;  // behind the start
      points.push_back(at(c, -side.depth));
      walk(side.corridor, 0.0);
      points.push_back(at(c, -side.depth));
    }
    if (farChild >= 0) {
      points.push_back(at(c, -length));
      walk(farChild, 0.0);
      points.push_back(at(c, -length));
    } else {
      points.push_back(at(c, std::min(deadEnd, entryZ)));
    }
    points.push_back(at(c, entryZ));
  }
};

}  // namespace

double yawOf(const glm::dvec3& d) { return std::atan2(-d.x, -d.z); }

std::vector<glm::dvec3> tourWaypoints(const Layout& layout, const std::vector<metrology::Dimensions>& boxes,
                                      const BuildingPlan& plan, const TourOptions& options) {
  Walker walker{layout, boxes, plan, options, {}};
  if (!boxes.empty()) walker.walk(0, options.startZ);
  // Drop repeated points (a junction reached and left at the same spot).
  std::vector<glm::dvec3> out;
  for (const glm::dvec3& p : walker.points) {
    if (out.empty() || glm::distance(out.back(), p) > 1e-6) out.push_back(p);
  }
  return out;
}

TourPath::TourPath(const std::vector<glm::dvec3>& waypoints, const TourOptions& options) {
  const double speed = std::max(0.05, options.walkSpeedMps);
  const double turnRate = glm::radians(std::max(1.0, options.turnSpeedDegPerS));
  if (waypoints.size() < 2) {
    const glm::dvec3 p = waypoints.empty() ? glm::dvec3(0, options.eyeHeightM, 0) : waypoints[0];
    pieces_.push_back({Piece::kTurn, p, p, p, 0.0, glm::two_pi<double>(), glm::two_pi<double>() / turnRate});
    duration_ = pieces_.back().duration;
    return;
  }
  // Start of the next straight run, after rounding the previous corner.
  glm::dvec3 cursor = waypoints[0];
  for (size_t i = 1; i < waypoints.size(); ++i) {
    const glm::dvec3 corner = waypoints[i];
    const glm::dvec3 dirIn = glm::normalize(corner - waypoints[i - 1]);
    const bool last = i + 1 == waypoints.size();
    const glm::dvec3 dirOut = last ? dirIn : glm::normalize(waypoints[i + 1] - corner);
    const double turn = wrapAngle(yawOf(dirOut) - yawOf(dirIn));
    const bool uTurn = std::abs(turn) > glm::radians(150.0);
    double r = 0;
    if (!last && !uTurn && std::abs(turn) > 1e-6) {
      r = std::min({options.cornerRadiusM, 0.45 * glm::distance(cursor, corner),
                    0.45 * glm::distance(corner, waypoints[i + 1])});
    }
    const glm::dvec3 lineEnd = corner - dirIn * r;
    if (glm::distance(cursor, lineEnd) > 1e-9) {
      pieces_.push_back({Piece::kLine, cursor, cursor, lineEnd, 0, 0, glm::distance(cursor, lineEnd) / speed});
    }
    if (r > 0) {
      const glm::dvec3 arcEnd = corner + dirOut * r;
      // A quadratic Bezier's length is close to the chord-and-control average.
      const double length = 0.5 * (glm::distance(lineEnd, arcEnd) + 2.0 * r);
      pieces_.push_back({Piece::kArc, lineEnd, corner, arcEnd, 0, 0, length / speed});
      cursor = arcEnd;
    } else {
      cursor = corner;
      if (uTurn || last) {
        // Turn on the spot: round at dead ends, and a full look back at the very end.
        const double from = yawOf(dirIn);
        const double to = last ? from + glm::pi<double>() : from + (turn >= 0 ? std::abs(turn) : -std::abs(turn));
        if (std::abs(to - from) > 1e-6) {
          pieces_.push_back({Piece::kTurn, corner, corner, corner, from, to, std::abs(to - from) / turnRate});
        }
      }
    }
  }
  for (const Piece& p : pieces_) duration_ += p.duration;
}

void TourPath::sample(double t, glm::dvec3& position, double& yawRad) const {
  t = std::clamp(t, 0.0, duration_);
  for (size_t i = 0; i < pieces_.size(); ++i) {
    const Piece& p = pieces_[i];
    if (t > p.duration && i + 1 < pieces_.size()) {
      t -= p.duration;
      continue;
    }
    const double u = p.duration > 0 ? std::clamp(t / p.duration, 0.0, 1.0) : 1.0;
    switch (p.kind) {
      case Piece::kLine:
        position = glm::mix(p.a, p.b, u);
        yawRad = yawOf(p.b - p.a);
        return;
      case Piece::kArc: {
        const double v = 1.0 - u;
        position = v * v * p.a + 2.0 * v * u * p.control + u * u * p.b;
        yawRad = yawOf(2.0 * v * (p.control - p.a) + 2.0 * u * (p.b - p.control));
        return;
      }
      case Piece::kTurn:
        position = p.a;
        yawRad = p.yaw0 + (p.yaw1 - p.yaw0) * smoothstep(u);
        return;
    }
  }
  position = glm::dvec3(0);
  yawRad = 0;
}

std::vector<engine::Camera> TourPath::cameras(int frames, float fieldOfViewRad) const {
  std::vector<engine::Camera> out;
  for (int i = 0; i < frames; ++i) {
    const double t = frames > 1 ? duration_ * i / (frames - 1) : 0.0;
    glm::dvec3 position;
    double yaw = 0;
    sample(t, position, yaw);
    engine::Camera camera;
    camera.position = glm::vec3(position);
    camera.orientation = glm::angleAxis(static_cast<float>(yaw), glm::vec3(0, 1, 0));
    camera.fieldOfViewRad = fieldOfViewRad;
    out.push_back(camera);
  }
  return out;
}

}  // namespace pw::modeling
