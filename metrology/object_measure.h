// Measuring objects in the photo (issue 25): points a person gives in the photo, placed
// in the measured corridor's frame (floor y = 0, metres; corridor_frame.h), and the
// distances and heights between them, each with its ± from every input of the
// measurement (the corners', the camera's, and the points' own pixels).
//
// A point is where its pixel's ray meets a surface of the corridor's box (the floor,
// the ceiling, a side wall, the far wall), or, for a point off every surface (a
// person's head, a lamp), the vertical through another point: the nearest point on
// it to the ray (single-view metrology's "height above the ground point below", here
// in 3D: Criminisi, Reid and Zisserman's construction, and the seed paper's section
// 2.1, which projects both ends of an object to the ground line).
//
//   auto located = locatePoints(measurement, {{"feet", {412, 540}, {PointSurface::kFloor}},
//                                            {"head", {410, 233}, {PointSurface::kAbove, "feet"}}});
//   height of "head" above "feet": located->at(1).m.y - located->at(0).m.y
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "base/result.h"
#include "metrology/measure.h"
#include "metrology/shot.h"

namespace pw::metrology {

struct LocatedPoint {
  std::string name;
  glm::dvec3 m{0.0};  // in the corridor's frame, metres
  // Horizontal distance from the camera's eye, and how far before the far wall (z + length).
  double fromCameraM = 0;
  double fromFarWallM = 0;
};

// Places each point (in order; kAbove names an earlier one). Errors: a name used twice
// or unknown, a ray that misses its surface (the point above the horizon on the floor,
// behind the camera), a ray parallel to the vertical it should meet.
Result<std::vector<LocatedPoint>> locatePoints(const Measurement& measurement, const std::vector<ImagePoint>& points);

struct ObjectResult {
  ObjectMeasure asked;
  double valueM = 0;
  double sigmaM = 0;  // one sigma: every input of the measurement and the points' pixels
  // Each source's part (their squares add up to sigmaM's): the corners, the points, and
  // the measurement's other inputs as MeasureOptions gives them sigmas.
  std::vector<std::pair<std::string, double>> sigmaSources;
};

struct PointMeasurement {
  std::vector<LocatedPoint> points;
  std::vector<ObjectResult> results;
  std::vector<glm::dvec3> pointSigmaM;  // per point, x y z
};

// Places the points by `measurement` (the shot measured with `options`) and works out
// each asked quantity, and each one's ± by measuring again with every input moved by
// its sigma either way: each corner's u and v (options.cornerSigmaPx), each point's
// u and v (pointSigmaPx), the focal length, camera height, principal point and lens
// distortion by options' sigmas (input_sigma.h's withInputSigmas sets them).
Result<PointMeasurement> measurePoints(const Shot& shot, const MeasureOptions& options, const Measurement& measurement,
                                       const std::vector<ImagePoint>& points, const std::vector<ObjectMeasure>& asked,
                                       double pointSigmaPx = 1.0);

}  // namespace pw::metrology
