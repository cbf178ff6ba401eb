#include "metrology/object_measure.h"

#include <cmath>
#include <functional>
#include <map>

#include "metrology/corridor_frame.h"
#include "metrology/distortion.h"

namespace pw::metrology {
namespace {

// Where the pinhole would show the photo's pixel, and the ray through it.
Result<glm::dvec3> rayOf(const Measurement& m, const ImagePoint& point) {
  glm::dvec2 px = point.px;
  if (!m.camera.distortion.isNone()) {
    const std::optional<glm::dvec2> pinhole = undistortPixel(m.camera, px);
    if (!pinhole) return makeError("point \"" + point.name + "\" lies where the lens's distortion cannot be undone");
    px = *pinhole;
  }
  return rayThroughPixel(m.camera, m.pose.worldFromCamera, px);
}

// Along the ray from `eye` in `dir`, where coordinate `axis` reaches `value`.
std::optional<glm::dvec3> meetPlane(const glm::dvec3& eye, const glm::dvec3& dir, int axis, double value) {
  if (std::abs(dir[axis]) < 1e-12) return std::nullopt;
  const double t = (value - eye[axis]) / dir[axis];
  if (!(t > 1e-9) || !std::isfinite(t)) return std::nullopt;
  return eye + t * dir;
}

const char* surfaceWords(PointSurface s) {
  switch (s) {
    case PointSurface::kFloor: return "the floor";
    case PointSurface::kCeiling: return "the ceiling";
    case PointSurface::kLeftWall: return "the left wall";
    case PointSurface::kRightWall: return "the right wall";
    case PointSurface::kFarWall: return "the far wall";
    case PointSurface::kAbove: return "the vertical";
  }
  return "?";
}

}  // namespace

std::string surfaceName(PointSurface surface) {
  switch (surface) {
    case PointSurface::kFloor: return "floor";
    case PointSurface::kCeiling: return "ceiling";
    case PointSurface::kLeftWall: return "wall:left";
    case PointSurface::kRightWall: return "wall:right";
    case PointSurface::kFarWall: return "wall:far";
    case PointSurface::kAbove: return "above";
  }
  return "?";
}

std::optional<PointSurface> surfaceFromName(const std::string& text, std::string* above) {
  for (PointSurface s : {PointSurface::kFloor, PointSurface::kCeiling, PointSurface::kLeftWall, PointSurface::kRightWall,
                         PointSurface::kFarWall}) {
    if (text == surfaceName(s)) return s;
  }
  if (text.rfind("above:", 0) == 0 && text.size() > 6) {
    if (above) *above = text.substr(6);
    return PointSurface::kAbove;
  }
  return std::nullopt;
}

const char* quantityName(ObjectQuantity quantity) {
  return quantity == ObjectQuantity::kDistance ? "distance" : "height";
}

Result<std::vector<LocatedPoint>> locatePoints(const Measurement& m, const std::vector<ImagePoint>& points) {
  std::vector<LocatedPoint> out;
  std::map<std::string, size_t> index;
  const glm::dvec3 eye = m.pose.positionM;
  const double halfWidth = 0.5 * m.size.widthM;
  for (const ImagePoint& point : points) {
    if (point.name.empty()) return makeError("a point needs a name");
    if (index.count(point.name)) return makeError("point \"" + point.name + "\" is given twice");
    if (!std::isfinite(point.px.x) || !std::isfinite(point.px.y)) {
      return makeError("point \"" + point.name + "\" is not a number");
    }
    auto ray = rayOf(m, point);
    if (!ray) return ray.error();
    std::optional<glm::dvec3> at;
    switch (point.on.surface) {
      case PointSurface::kFloor: at = meetPlane(eye, *ray, 1, 0.0); break;
      case PointSurface::kCeiling: at = meetPlane(eye, *ray, 1, m.size.heightM); break;
      case PointSurface::kLeftWall: at = meetPlane(eye, *ray, 0, -halfWidth); break;
      case PointSurface::kRightWall: at = meetPlane(eye, *ray, 0, halfWidth); break;
      case PointSurface::kFarWall: at = meetPlane(eye, *ray, 2, -m.size.lengthM); break;
      case PointSurface::kAbove: {
        const auto base = index.find(point.on.above);
        if (base == index.end()) {
          return makeError("point \"" + point.name + "\" stands above \"" + point.on.above +
                           "\", which is not a point given before it");
        }
        // The nearest point of the vertical through the base to the ray.
        const glm::dvec3 b = out[base->second].m;
        const glm::dvec3 w0 = eye - b;
        const double along = ray->y, denom = 1.0 - along * along;
        if (denom < 1e-9) {
          return makeError("point \"" + point.name + "\": the camera looks straight along the vertical through \"" +
                           point.on.above + "\"");
        }
        const double d = glm::dot(*ray, w0);
        const double t = (along * w0.y - d) / denom, s = (w0.y - along * d) / denom;
        if (t > 1e-9 && std::isfinite(s)) at = b + glm::dvec3(0, s, 0);
        break;
      }
    }
    if (!at) {
      return makeError("point \"" + point.name + "\" at (" + std::to_string(point.px.x) + ", " +
                       std::to_string(point.px.y) + ") px: its ray does not meet " + surfaceWords(point.on.surface) +
                       " in front of the camera");
    }
    LocatedPoint located;
    located.name = point.name;
    located.m = *at;
    located.fromCameraM = std::hypot(at->x - eye.x, at->z - eye.z);
    located.fromFarWallM = at->z + m.size.lengthM;
    index[point.name] = out.size();
    out.push_back(located);
  }
  return out;
}

namespace {

// The asked quantities, then each point's x, y, z: what the ± is worked out for.
Result<std::vector<double>> quantities(const Measurement& m, const std::vector<ImagePoint>& points,
                                       const std::vector<ObjectMeasure>& asked, std::vector<LocatedPoint>* located) {
  auto placed = locatePoints(m, points);
  if (!placed) return placed.error();
  std::map<std::string, glm::dvec3> at;
  for (const LocatedPoint& p : *placed) at[p.name] = p.m;
  std::vector<double> q;
  for (const ObjectMeasure& a : asked) {
    const auto from = at.find(a.from), to = at.find(a.to);
    if (from == at.end()) return makeError(std::string(quantityName(a.quantity)) + " from \"" + a.from + "\": no such point");
    if (to == at.end()) return makeError(std::string(quantityName(a.quantity)) + " to \"" + a.to + "\": no such point");
    q.push_back(a.quantity == ObjectQuantity::kDistance ? glm::length(to->second - from->second)
                                                        : to->second.y - from->second.y);
  }
  for (const LocatedPoint& p : *placed) q.insert(q.end(), {p.m.x, p.m.y, p.m.z});
  if (located) *located = std::move(*placed);
  return q;
}

}  // namespace

Result<PointMeasurement> measurePoints(const Shot& shot, const MeasureOptions& options, const Measurement& measurement,
                                       const std::vector<ImagePoint>& points, const std::vector<ObjectMeasure>& asked,
                                       double pointSigmaPx) {
  const Measurement* m = &measurement;
  PointMeasurement out;
  auto base = quantities(*m, points, asked, &out.points);
  if (!base) return base.error();
  const size_t n = base->size();

  // Measured again with one input moved: the camera as this measurement found it (its
  // focal length, principal point and lens fixed), no sigmas of its own.
  Shot fixed = shot;
  fixed.focalPx = m->camera.focalPx;
  fixed.focalMm.reset();
  fixed.principalPointPx = m->camera.principalPointPx;
  fixed.distortion = m->camera.distortion;
  MeasureOptions plain = options;
  plain.focalSigmaRelative = plain.principalPointSigmaPx = plain.distortionSigmaK1 = plain.cameraHeightSigmaM = 0;
  plain.distortionFromCorners = false;
  // Half the spread of the quantities with the input moved by -1 and +1 sigma.
  const auto spread = [&](const std::function<Result<std::vector<double>>(double)>& at) -> std::vector<double> {
    auto lo = at(-1.0), hi = at(1.0);
    std::vector<double> s(n, 0.0);
    for (size_t i = 0; i < n; ++i) {
      if (lo && hi) s[i] = 0.5 * std::abs((*hi)[i] - (*lo)[i]);
      else if (lo) s[i] = std::abs((*lo)[i] - (*base)[i]);
      else if (hi) s[i] = std::abs((*hi)[i] - (*base)[i]);
    }
    return s;
  };
  const auto remeasured = [&](const Shot& moved) -> Result<std::vector<double>> {
    auto again = measureCorridor(moved, plain);
    if (!again) return again.error();
    return quantities(*again, points, asked, nullptr);
  };
  std::vector<std::pair<std::string, std::vector<double>>> sources;
  const auto addSource = [&](const std::string& name, std::vector<double> variance) {
    for (double& v : variance) v = std::sqrt(v);
    sources.emplace_back(name, std::move(variance));
  };
  const auto accumulate = [&](std::vector<double>& variance, const std::vector<double>& s) {
    for (size_t i = 0; i < n; ++i) variance[i] += s[i] * s[i];
  };

  std::vector<double> corners(n, 0.0);
  if (options.cornerSigmaPx > 0) {
    for (int k = 0; k < kCornerCount; ++k) {
      for (int axis = 0; axis < 2; ++axis) {
        accumulate(corners, spread([&](double side) {
                     Shot moved = fixed;
                     moved.cornersPx[k][axis] += side * options.cornerSigmaPx;
                     return remeasured(moved);
                   }));
      }
    }
    addSource("the corners", corners);
  }
  std::vector<double> pixels(n, 0.0);
  if (pointSigmaPx > 0) {
    for (size_t p = 0; p < points.size(); ++p) {
      for (int axis = 0; axis < 2; ++axis) {
        accumulate(pixels, spread([&](double side) {
                     std::vector<ImagePoint> moved = points;
                     moved[p].px[axis] += side * pointSigmaPx;
                     return quantities(*m, moved, asked, nullptr);
                   }));
      }
    }
    addSource("the points", pixels);
  }
  if (options.focalSigmaRelative > 0) {
    std::vector<double> v(n, 0.0);
    accumulate(v, spread([&](double side) {
                 Shot moved = fixed;
                 moved.focalPx *= std::exp(side * options.focalSigmaRelative);
                 return remeasured(moved);
               }));
    addSource(options.focalSigmaName, v);
  }
  if (options.cameraHeightSigmaM > 0 && shot.cameraHeightM) {
    std::vector<double> v(n, 0.0);
    accumulate(v, spread([&](double side) {
                 Shot moved = fixed;
                 moved.cameraHeightM = *shot.cameraHeightM + side * options.cameraHeightSigmaM;
                 if (!(*moved.cameraHeightM > 0)) return Result<std::vector<double>>(makeError("no height"));
                 return remeasured(moved);
               }));
    addSource(options.cameraHeightSigmaName, v);
  }
  if (options.principalPointSigmaPx > 0) {
    std::vector<double> v(n, 0.0);
    for (int axis = 0; axis < 2; ++axis) {
      accumulate(v, spread([&](double side) {
                   Shot moved = fixed;
                   (*moved.principalPointPx)[axis] += side * options.principalPointSigmaPx;
                   return remeasured(moved);
                 }));
    }
    addSource("the principal point", v);
  }
  if (options.distortionSigmaK1 > 0) {
    std::vector<double> v(n, 0.0);
    accumulate(v, spread([&](double side) {
                 Shot moved = fixed;
                 moved.distortion->k1 += side * options.distortionSigmaK1;
                 return remeasured(moved);
               }));
    addSource("the lens distortion", v);
  }

  for (size_t i = 0; i < asked.size(); ++i) {
    ObjectResult r;
    r.asked = asked[i];
    r.valueM = (*base)[i];
    double variance = 0;
    for (const auto& [name, sigma] : sources) {
      r.sigmaSources.emplace_back(name, sigma[i]);
      variance += sigma[i] * sigma[i];
    }
    r.sigmaM = std::sqrt(variance);
    if (!std::isfinite(r.valueM) || !std::isfinite(r.sigmaM)) {
      return makeError(std::string(quantityName(r.asked.quantity)) + " " + r.asked.from + "-" + r.asked.to +
                       " is not a finite number");
    }
    out.results.push_back(std::move(r));
  }
  for (size_t p = 0; p < out.points.size(); ++p) {
    glm::dvec3 s(0.0);
    for (int axis = 0; axis < 3; ++axis) {
      double variance = 0;
      for (const auto& [name, sigma] : sources) variance += sigma[asked.size() + 3 * p + axis] * sigma[asked.size() + 3 * p + axis];
      s[axis] = std::sqrt(variance);
    }
    out.pointSigmaM.push_back(s);
  }
  return out;
}

}  // namespace pw::metrology
