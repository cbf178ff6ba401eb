#include "metrology/box_fit.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "metrology/least_squares.h"
#include "metrology/uncertainty.h"

namespace pw::metrology {

namespace {

// OpenCV camera coordinates (x right, y down, z forward) of the ray or direction of
// a homogeneous image point: K⁻¹·x.
glm::dvec3 backProject(const Intrinsics& k, const glm::dvec3& x) {
  return {(x.x - k.principalPointPx.x * x.z) / k.focalPx, (x.y - k.principalPointPx.y * x.z) / k.focalPx, x.z};
}

// Chooses the sign of direction `d` (OpenCV camera coordinates) so that moving from
// the 3D point seen at pixel `a` along d moves its image towards pixel `b`.
glm::dvec3 orientTowards(const Intrinsics& k, glm::dvec3 d, const glm::dvec2& a, const glm::dvec2& b) {
  const glm::dvec3 ray = backProject(k, glm::dvec3(a, 1.0));  // z = 1
  const glm::dvec2 imageMotion(d.x - ray.x * d.z, d.y - ray.y * d.z);
  if (glm::dot(imageMotion, b - a) < 0) d = -d;
  return glm::normalize(d);
}

// OpenCV camera axes to the engine's (x right, y up, looking along -z).
const glm::dmat3 kCvToGl(1, 0, 0, 0, -1, 0, 0, 0, -1);

CameraPose poseFrom(const std::vector<double>& p, double cameraHeightM) {
  return makeCameraPose(glm::degrees(p[kYaw]), glm::degrees(p[kPitch]), glm::degrees(p[kRoll]),
                        glm::dvec3(p[kCameraX], cameraHeightM, p[kCameraZ]));
}

}  // namespace

Result<std::array<glm::dvec2, kCornerCount>> projectCorridor(const Intrinsics& camera, const CameraPose& pose,
                                                             double widthM, double heightM, double lengthM) {
  const auto corners = corridorCorners(widthM, heightM, lengthM);
  std::array<glm::dvec2, kCornerCount> out{};
  for (int i = 0; i < kCornerCount; ++i) {
    const glm::dvec3 p = projectToPixel(camera, pose, corners[i]);
    if (!(p.z > 1e-9)) return makeError(std::string("corner ") + cornerName(i) + " of the box is behind the camera");
    out[i] = glm::dvec2(p);
  }
  return out;
}

Result<glm::dmat3> rotationFromVanishingPoints(const CorridorVanishing& v, const Intrinsics& k,
                                               const std::array<glm::dvec2, kCornerCount>& c) {
  // World axes seen from the camera: +X (right), +Y (up), -Z (towards the far wall).
  const glm::dvec3 right = orientTowards(k, backProject(k, v.horizontal.homogeneous), c[P3], c[P4]);
  const glm::dvec3 up = orientTowards(k, backProject(k, v.vertical.homogeneous), c[P3], c[P1]);
  const glm::dvec3 far = orientTowards(k, backProject(k, v.corridor.homogeneous), c[P5], c[P3]);
  cv::Matx33d m(right.x, up.x, -far.x, right.y, up.y, -far.y, right.z, up.z, -far.z);
  cv::Matx33d u, vt;
  cv::Matx31d w;
  cv::SVD::compute(m, w, u, vt);
  cv::Matx33d cameraFromWorld = u * vt;
  if (cv::determinant(cameraFromWorld) < 0) {
    return makeError("the corners' left/right and up/down directions are mirrored; check the corner order");
  }
  glm::dmat3 r;  // world from OpenCV camera = transpose
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) r[row][col] = cameraFromWorld(row, col);  // r[col][row] = (R^T)(row, col)
  }
  return r * kCvToGl;
}

Result<BoxFit> fitCorridorBox(const std::array<glm::dvec2, kCornerCount>& c, const Intrinsics& camera, double h,
                              const CorridorVanishing& vanishing) {
  if (!(h > 0) || !std::isfinite(h)) return makeError("the camera height must be a positive number");
  auto rotation = rotationFromVanishingPoints(vanishing, camera, c);
  if (!rotation) return rotation.error();

  // Start: intersect the floor corners' rays with the floor (the camera at (0, h, 0)),
  // and the top corners' rays with the verticals through the floor corners below them.
  constexpr int kFloor[4] = {P3, P4, P5, P6};
  constexpr int kTopOver[4] = {P1, P2, P7, P8};
  std::array<glm::dvec3, 4> floor{};
  for (int i = 0; i < 4; ++i) {
    const glm::dvec3 d = rayThroughPixel(camera, *rotation, c[kFloor[i]]);
    if (!(d.y < -1e-9)) {
      return makeError(std::string("floor corner ") + cornerName(kFloor[i]) +
                       " is not below the horizon; the floor corners must lie below it");
    }
    floor[i] = glm::dvec3(0, h, 0) + d * (-h / d.y);
  }
  double heightSum = 0;
  for (int i = 0; i < 4; ++i) {
    const glm::dvec3 d = rayThroughPixel(camera, *rotation, c[kTopOver[i]]);
    const glm::dvec2 dxz(d.x, d.z), fxz(floor[i].x, floor[i].z);
    const double t = glm::dot(dxz, fxz) / std::max(glm::dot(dxz, dxz), 1e-300);
    heightSum += h + t * d.y;
  }
  const glm::dvec3 ypr = yawPitchRollFromRotation(*rotation);
  std::vector<double> p(kBoxParameterCount);
  p[kWidth] = 0.5 * ((floor[1].x - floor[0].x) + (floor[3].x - floor[2].x));
  p[kHeight] = heightSum / 4;
  const double nearZ = 0.5 * (floor[2].z + floor[3].z), farZ = 0.5 * (floor[0].z + floor[1].z);
  p[kLength] = nearZ - farZ;
  p[kCameraX] = -0.25 * (floor[0].x + floor[1].x + floor[2].x + floor[3].x);
  p[kCameraZ] = -nearZ;
  p[kYaw] = ypr.x;
  p[kPitch] = ypr.y;
  p[kRoll] = ypr.z;
  if (!(p[kWidth] > 0) || !(p[kHeight] > 0) || !(p[kLength] > 0)) {
    return makeError("the corners do not show a corridor seen from inside (a dimension comes out negative); "
                     "check the corner order");
  }

  auto residuals = [&](const std::vector<double>& q, std::vector<double>& r) -> bool {
    if (!(q[kWidth] > 0) || !(q[kHeight] > 0) || !(q[kLength] > 0)) return false;
    auto projected = projectCorridor(camera, poseFrom(q, h), q[kWidth], q[kHeight], q[kLength]);
    if (!projected) return false;
    for (int i = 0; i < kCornerCount; ++i) {
      r[2 * i] = (*projected)[i].x - c[i].x;
      r[2 * i + 1] = (*projected)[i].y - c[i].y;
    }
    return true;
  };
  const double metric = std::max({p[kWidth], p[kHeight], p[kLength], h});
  std::vector<double> steps(kBoxParameterCount, 1e-6 * metric);
  steps[kYaw] = steps[kPitch] = steps[kRoll] = 1e-6;
  auto solved = levenbergMarquardt(residuals, p, steps, 2 * kCornerCount);
  if (!solved) return makeError("the box fit failed: " + solved.message() + "; check the corners");

  BoxFit fit;
  const std::vector<double>& q = solved->parameters;
  fit.widthM = q[kWidth];
  fit.heightM = q[kHeight];
  fit.lengthM = q[kLength];
  fit.pose = poseFrom(q, h);
  fit.iterations = solved->iterations;
  auto projected = projectCorridor(camera, fit.pose, fit.widthM, fit.heightM, fit.lengthM);
  if (!projected) return makeError("the fitted box has " + projected.message() + "; check the corners");
  fit.reprojectedPx = *projected;
  fit.reprojectionRmsPx = std::sqrt(solved->cost / kCornerCount);
  auto covariance = fitCovariance(solved->jacobian, 1.0);
  if (!covariance) return covariance.error();
  fit.parameterCovariance = *covariance;
  return fit;
}

}  // namespace pw::metrology
