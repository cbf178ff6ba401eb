// The corridor's model frame and the camera in it.
//
// Model frame (what the 3D model is built in): right-handed, metres, Y up, floor at
// y = 0, the near end (the plane of P5..P8) at z = 0, the far wall at z = -length,
// x from -width/2 (left wall) to +width/2 (right wall). So the corners are
//   P1 (-W/2, H, -L)  P2 (W/2, H, -L)  P3 (-W/2, 0, -L)  P4 (W/2, 0, -L)
//   P5 (-W/2, 0,  0)  P6 (W/2, 0,  0)  P7 (-W/2, H,  0)  P8 (W/2, H,  0).
//
// Camera convention: the engine's (and VRML97's): the camera looks along its local
// -Z with +Y up and +X right. `worldFromCamera` has the camera's right, up and back
// axes as its columns, so a renderer using it as the camera orientation (and
// `positionM` as the eye) with the shot's focal length and principal point draws
// the model exactly where the photo shows it. Its angles:
//   worldFromCamera = Ry(yaw) · Rx(pitch) · Rz(roll)
// yaw > 0 turns the camera to the left (about +Y), pitch > 0 tilts it up (about the
// camera's +X), roll > 0 turns it anticlockwise about its viewing axis as seen from
// behind the camera, so that the horizon falls to the right in the image.
#pragma once

#include <array>

#include <glm/glm.hpp>

#include "metrology/distortion.h"
#include "metrology/shot.h"

namespace pw::metrology {

// The square-pixel pinhole a measurement solves for, in the photo's own pixels.
// engine::Intrinsics (engine/scene/scene.h) is the renderer's lens, fitted to frames of
// any size; two types because metrology may not see the engine nor the engine
// metrology, and the one layer both see (base/) is std only. modeling::photoCamera is
// the one place this becomes that.
struct Intrinsics {
  double focalPx = 0;
  glm::dvec2 principalPointPx{0.0};  // pixel centres at integer coordinates
  // The lens's radial distortion (distortion.h). projectToPixel and rayThroughPixel
  // are the pinhole's and ignore it: distortPixel / undistortPixel take a pinhole
  // pixel to the photo's and back.
  RadialDistortion distortion;
};

struct CameraPose {
  glm::dmat3 worldFromCamera{1.0};  // columns: right, up, back (camera looks along -column 2)
  glm::dvec3 positionM{0.0};        // the eye, in the model frame
  double yawDeg = 0;
  double pitchDeg = 0;
  double rollDeg = 0;
};

// Ry(yaw) · Rx(pitch) · Rz(roll), angles in radians.
glm::dmat3 rotationFromYawPitchRoll(double yawRad, double pitchRad, double rollRad);
// The inverse of the above: (yaw, pitch, roll) in radians, pitch in [-pi/2, pi/2].
glm::dvec3 yawPitchRollFromRotation(const glm::dmat3& worldFromCamera);
// A pose from its angles (degrees) and eye position; fills the rotation.
CameraPose makeCameraPose(double yawDeg, double pitchDeg, double rollDeg, const glm::dvec3& positionM);

// The eight corners P1..P8 of a corridor box in the model frame (see above).
std::array<glm::dvec3, kCornerCount> corridorCorners(double widthM, double heightM, double lengthM);

// Pixel (u, v) of a model-frame point and its depth in metres in front of the camera
// (negative: behind it, and then u, v are meaningless). engine::projectToPixel is the
// same projection for the renderer's Camera (see Intrinsics for why there are two);
// tests/metrology/geometry_test.cpp holds both to the same pixels.
glm::dvec3 projectToPixel(const Intrinsics& camera, const CameraPose& pose, const glm::dvec3& pointM);

// The camera ray through pixel `px`, as a unit direction in the model frame.
glm::dvec3 rayThroughPixel(const Intrinsics& camera, const glm::dmat3& worldFromCamera, const glm::dvec2& px);

}  // namespace pw::metrology
