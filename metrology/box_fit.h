// photowalk's general solution: a calibrated pinhole camera with full rotation and a
// corridor box fitted to all eight corners.
//
// The rotation comes from the vanishing directions (the corridor direction is
// K⁻¹·VP, the horizontal and vertical ones from the far wall's edges; Hartley &
// Zisserman 8.6.2), the floor plane y = 0 lies the camera height below the eye, and
// the box (width, height, length) and pose (camera x and z, yaw, pitch, roll) are then
// refined by Levenberg-Marquardt on the reprojection error of P1..P8.
#pragma once

#include <array>

#include <glm/glm.hpp>
#include <opencv2/core/mat.hpp>

#include "base/result.h"
#include "metrology/corridor_frame.h"
#include "metrology/shot.h"
#include "metrology/vanishing.h"

namespace pw::metrology {

// Order of the fitted parameters (and of BoxFit::parameterCovariance).
enum BoxParameter : int { kWidth = 0, kHeight, kLength, kCameraX, kCameraZ, kYaw, kPitch, kRoll };
inline constexpr int kBoxParameterCount = 8;

struct BoxFit {
  double widthM = 0;
  double heightM = 0;
  double lengthM = 0;
  CameraPose pose;  // positionM.y is the camera height the fit was given
  // RMS over the eight corners of the distance (px) between each corner and the
  // fitted box's projection of it.
  double reprojectionRmsPx = 0;
  std::array<glm::dvec2, kCornerCount> reprojectedPx{};
  // 8x8 (CV_64F) covariance of the parameters in BoxParameter order, metres and
  // radians, for corners with a standard deviation of 1 px in u and in v.
  cv::Mat parameterCovariance;
  int iterations = 0;
};

// The camera's rotation (world from camera, corridor_frame.h) from the three
// vanishing points, made orthonormal by the nearest rotation (SVD). `cornersPx`
// orient the directions (towards the far wall, to the right, up).
Result<glm::dmat3> rotationFromVanishingPoints(const CorridorVanishing& vanishing, const Intrinsics& camera,
                                               const std::array<glm::dvec2, kCornerCount>& cornersPx);

// Fits the box to the corners for a camera `cameraHeightM` above the floor. Fails
// (one line) when a floor corner is not below the horizon, the fit does not give a
// box in front of the camera, or the corners do not determine it.
Result<BoxFit> fitCorridorBox(const std::array<glm::dvec2, kCornerCount>& cornersPx, const Intrinsics& camera,
                              double cameraHeightM, const CorridorVanishing& vanishing);

// Projects a box and pose to the eight corners (px). Fails when a corner is not in
// front of the camera.
Result<std::array<glm::dvec2, kCornerCount>> projectCorridor(const Intrinsics& camera, const CameraPose& pose,
                                                             double widthM, double heightM, double lengthM);

}  // namespace pw::metrology
