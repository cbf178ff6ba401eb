#include "metrology/shot_check.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace pw::metrology {

namespace {

bool finite(const glm::dvec2& p) { return std::isfinite(p.x) && std::isfinite(p.y); }

double cross(const glm::dvec2& a, const glm::dvec2& b) { return a.x * b.y - a.y * b.x; }

// "far wall" rather than the file name "far_wall".
std::string spokenName(int plane) {
  std::string name = planeName(static_cast<Plane>(plane));
  std::replace(name.begin(), name.end(), '_', ' ');
  return name;
}

std::string quadName(int plane) {
  const auto& q = kPlaneCorners[plane];
  return spokenName(plane) + " quad " + cornerName(q[0]) + "-" + cornerName(q[1]) + "-" +
         cornerName(q[2]) + "-" + cornerName(q[3]);
}

Status checkQuad(const Shot& shot, int plane) {
  const auto& q = kPlaneCorners[plane];
  const std::string name = spokenName(plane);
  for (int i = 0; i < 4; ++i) {
    for (int j = i + 1; j < 4; ++j) {
      if (glm::length(shot.cornersPx[q[i]] - shot.cornersPx[q[j]]) < 0.5) {
        return makeError(std::string("corners ") + cornerName(q[i]) + " and " + cornerName(q[j]) + " coincide; the " +
                         name + " plane is degenerate");
      }
    }
  }
  // Turning at each corner: positive cross product = clockwise on screen (v down).
  int positive = 0, negative = 0;
  for (int i = 0; i < 4; ++i) {
    const glm::dvec2 a = shot.cornersPx[q[i]], b = shot.cornersPx[q[(i + 1) % 4]], c = shot.cornersPx[q[(i + 2) % 4]];
    const glm::dvec2 e1 = b - a, e2 = c - b;
    const double sine = cross(e1, e2) / (glm::length(e1) * glm::length(e2));
    if (std::abs(sine) < std::sin(glm::radians(0.5))) {
      return makeError(std::string("corners ") + cornerName(q[i]) + ", " + cornerName(q[(i + 1) % 4]) + " and " +
                       cornerName(q[(i + 2) % 4]) + " are collinear; the " + name + " plane is degenerate");
    }
    (sine > 0 ? positive : negative)++;
  }
  if (negative == 4) {
    return makeError("the " + quadName(plane) +
                     " runs anticlockwise: left and right (or top and bottom) corners are swapped");
  }
  if (negative > 0) {
    return makeError("the " + quadName(plane) + " crosses itself or is not convex; check the corner order");
  }
  return {};
}

}  // namespace

Result<Intrinsics> shotIntrinsics(const Shot& shot) {
  if (shot.imageWidth <= 0 || shot.imageHeight <= 0) return makeError("the image has no pixels (zero size)");
  Intrinsics k;
  k.focalPx = shot.focalPx;
  if (!(k.focalPx > 0) && shot.focalOverSensorWidth) k.focalPx = *shot.focalOverSensorWidth * shot.imageWidth;
  if (!std::isfinite(k.focalPx) || !(k.focalPx > 0)) return makeError("the focal length must be a positive number");
  k.principalPointPx = shot.principalPoint();
  if (!finite(k.principalPointPx)) return makeError("the principal point is not finite");
  return k;
}

Status checkShot(const Shot& shot) {
  auto k = shotIntrinsics(shot);
  if (!k) return k.error();
  if (shot.cameraHeightM && !(std::isfinite(*shot.cameraHeightM) && *shot.cameraHeightM > 0)) {
    return makeError("camera_height_m must be a positive number of metres");
  }
  if (shot.reference) {
    const ReferenceLength& r = *shot.reference;
    if (r.from < 0 || r.from >= kCornerCount || r.to < 0 || r.to >= kCornerCount || r.from == r.to) {
      return makeError("the reference length needs two different corners among P1..P8");
    }
    if (!(std::isfinite(r.lengthM) && r.lengthM > 0)) return makeError("the reference length_m must be a positive number");
  }
  if (!shot.cameraHeightM && !shot.reference) {
    return makeError("give camera_height_m or a reference length; without one the scale is unknown");
  }
  const double w = shot.imageWidth, h = shot.imageHeight;
  for (int i = 0; i < kCornerCount; ++i) {
    const glm::dvec2 p = shot.cornersPx[i];
    if (!finite(p)) return makeError(std::string("corner ") + cornerName(i) + " is not a finite number");
    if (p.x < -w || p.x > 2 * w || p.y < -h || p.y > 2 * h) {
      return makeError(std::string("corner ") + cornerName(i) + " lies more than the image's size outside the " +
                       std::to_string(shot.imageWidth) + "x" + std::to_string(shot.imageHeight) + " image");
    }
  }
  for (int plane = 0; plane < kPlaneCount; ++plane) PW_TRY(checkQuad(shot, plane));
  return {};
}

}  // namespace pw::metrology
