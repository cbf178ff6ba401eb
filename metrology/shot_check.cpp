#include "metrology/shot_check.h"

#include <algorithm>
#include <array>
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

// Coincident or collinear corners of one plane.
Status checkDegenerate(const Shot& shot, int plane) {
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
  for (int i = 0; i < 4; ++i) {
    const glm::dvec2 a = shot.cornersPx[q[i]], b = shot.cornersPx[q[(i + 1) % 4]], c = shot.cornersPx[q[(i + 2) % 4]];
    const glm::dvec2 e1 = b - a, e2 = c - b;
    if (std::abs(cross(e1, e2)) / (glm::length(e1) * glm::length(e2)) < std::sin(glm::radians(0.5))) {
      return makeError(std::string("corners ") + cornerName(q[i]) + ", " + cornerName(q[(i + 1) % 4]) + " and " +
                       cornerName(q[(i + 2) % 4]) + " are collinear; the " + name + " plane is degenerate");
    }
  }
  return {};
}

enum class Winding { kClockwise, kAnticlockwise, kCrossed };

// Turning at each corner: a positive cross product is clockwise on screen (v down).
Winding windingOf(const Shot& shot, int plane) {
  const auto& q = kPlaneCorners[plane];
  int positive = 0;
  for (int i = 0; i < 4; ++i) {
    const glm::dvec2 a = shot.cornersPx[q[i]], b = shot.cornersPx[q[(i + 1) % 4]], c = shot.cornersPx[q[(i + 2) % 4]];
    positive += cross(b - a, c - b) > 0 ? 1 : 0;
  }
  return positive == 4 ? Winding::kClockwise : positive == 0 ? Winding::kAnticlockwise : Winding::kCrossed;
}

// Every quad must run clockwise as kPlaneCorners lists it; when some do not, say
// which corners were most likely confused.
Status checkWinding(const Shot& shot) {
  std::array<Winding, kPlaneCount> w{};
  for (int plane = 0; plane < kPlaneCount; ++plane) w[plane] = windingOf(shot, plane);
  for (int plane = 0; plane < kPlaneCount; ++plane) {
    if (w[plane] == Winding::kCrossed) {
      return makeError("the " + quadName(plane) + " crosses itself or is not convex; check the corner order");
    }
  }
  const int far = static_cast<int>(Plane::kFarWall);
  bool othersAllReversed = true;
  for (int plane = 0; plane < kPlaneCount; ++plane) {
    if (plane != far) othersAllReversed = othersAllReversed && w[plane] == Winding::kAnticlockwise;
  }
  const auto& c = shot.cornersPx;
  if (w[far] == Winding::kClockwise && othersAllReversed) {
    return makeError("the far and near corners are swapped: P1..P4 are the far wall's corners, P5..P8 the near end's");
  }
  if (w[far] == Winding::kAnticlockwise) {
    if (c[P1].y + c[P2].y > c[P3].y + c[P4].y) {
      return makeError("top and bottom corners are swapped: P1, P2, P7, P8 are the top (ceiling) corners");
    }
    if (c[P1].x + c[P3].x > c[P2].x + c[P4].x) {
      return makeError("left and right corners are swapped: P1, P3, P5, P7 are the left wall's corners");
    }
  }
  for (int plane = 0; plane < kPlaneCount; ++plane) {
    if (w[plane] == Winding::kAnticlockwise) {
      return makeError("the " + quadName(plane) +
                       " runs anticlockwise, as if seen from outside the corridor; check its corners' order");
    }
  }
  return {};
}

}  // namespace

Result<Intrinsics> shotIntrinsics(const Shot& shot) {
  if (shot.imageWidth <= 0 || shot.imageHeight <= 0) return makeError("the image has no pixels (zero size)");
  Intrinsics k;
  k.focalPx = shot.focalPx;
  if (!(k.focalPx > 0) && shot.focalMm) k.focalPx = shot.focalMm->pixels(shot.imageWidth);
  if (!std::isfinite(k.focalPx) || !(k.focalPx > 0)) return makeError("the focal length must be a positive number");
  k.principalPointPx = shot.principalPoint();
  if (!finite(k.principalPointPx)) return makeError("the principal point is not finite");
  k.distortion = shot.distortion.value_or(RadialDistortion{});
  PW_TRY(checkDistortion(k.distortion));
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
  for (int plane = 0; plane < kPlaneCount; ++plane) PW_TRY(checkDegenerate(shot, plane));
  return checkWinding(shot);
}

}  // namespace pw::metrology
