#include "metrology/corridor_frame.h"

#include <algorithm>
#include <cmath>

namespace pw::metrology {

glm::dmat3 rotationFromYawPitchRoll(double yaw, double pitch, double roll) {
  const double cy = std::cos(yaw), sy = std::sin(yaw);
  const double cp = std::cos(pitch), sp = std::sin(pitch);
  const double cr = std::cos(roll), sr = std::sin(roll);
  // glm is column-major: constructor arguments run down the columns.
  const glm::dmat3 ry(cy, 0, -sy, 0, 1, 0, sy, 0, cy);
  const glm::dmat3 rx(1, 0, 0, 0, cp, sp, 0, -sp, cp);
  const glm::dmat3 rz(cr, sr, 0, -sr, cr, 0, 0, 0, 1);
  return ry * rx * rz;
}

glm::dvec3 yawPitchRollFromRotation(const glm::dmat3& r) {
  // With R = Ry Rx Rz, row 1 is (cp sr, cp cr, -sp) and column 2 is (sy cp, -sp, cy cp).
  // glm indexes [column][row].
  const double pitch = std::asin(std::clamp(-r[2][1], -1.0, 1.0));
  const double roll = std::atan2(r[0][1], r[1][1]);
  const double yaw = std::atan2(r[2][0], r[2][2]);
  return {yaw, pitch, roll};
}

CameraPose makeCameraPose(double yawDeg, double pitchDeg, double rollDeg, const glm::dvec3& positionM) {
  CameraPose pose;
  pose.yawDeg = yawDeg;
  pose.pitchDeg = pitchDeg;
  pose.rollDeg = rollDeg;
  pose.positionM = positionM;
  pose.worldFromCamera = rotationFromYawPitchRoll(glm::radians(yawDeg), glm::radians(pitchDeg), glm::radians(rollDeg));
  return pose;
}

std::array<glm::dvec3, kCornerCount> corridorCorners(double w, double h, double l) {
  const double x0 = -0.5 * w, x1 = 0.5 * w;
  return {glm::dvec3(x0, h, -l), glm::dvec3(x1, h, -l), glm::dvec3(x0, 0, -l), glm::dvec3(x1, 0, -l),
          glm::dvec3(x0, 0, 0),  glm::dvec3(x1, 0, 0),  glm::dvec3(x0, h, 0),  glm::dvec3(x1, h, 0)};
}

glm::dvec3 projectToPixel(const Intrinsics& camera, const CameraPose& pose, const glm::dvec3& pointM) {
  const glm::dvec3 c = glm::transpose(pose.worldFromCamera) * (pointM - pose.positionM);
  const double depth = -c.z;
  return {camera.principalPointPx.x + camera.focalPx * c.x / depth,
          camera.principalPointPx.y - camera.focalPx * c.y / depth, depth};
}

glm::dvec3 rayThroughPixel(const Intrinsics& camera, const glm::dmat3& worldFromCamera, const glm::dvec2& px) {
  const glm::dvec3 local((px.x - camera.principalPointPx.x) / camera.focalPx,
                         -(px.y - camera.principalPointPx.y) / camera.focalPx, -1.0);
  return glm::normalize(worldFromCamera * local);
}

}  // namespace pw::metrology
