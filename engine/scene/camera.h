// Cameras: where the eye is, where it looks, and how it projects to pixels.
//
// Conventions (as VRML97): the camera looks along its local -Z, +Y is up, +X right.
// Pixel coordinates have their origin at the top-left pixel's centre, u right,
// v down (OpenCV's convention, the one shot files use). Clip space is Vulkan's:
// y down, depth 0 (near) .. 1 (far).
#pragma once

#include <optional>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "engine/scene/scene.h"

namespace pw::engine {

struct Camera {
  glm::vec3 position{0.0f};
  glm::quat orientation{1.0f, 0.0f, 0.0f, 0.0f};  // camera-local axes to world
  float fieldOfViewRad = kDefaultFieldOfViewRad;  // VRML meaning: the smaller of the two angles
  // When set, overrides fieldOfViewRad: a photo's camera (scene.h), for frames that
  // line up with the photo pixel for pixel at its size (intrinsicsFor, other sizes).
  std::optional<Intrinsics> intrinsics;
  float nearM = 0.05f;
  float farM = 2000.0f;
  // How many times finer than the image it stands for the frame is drawn (a
  // supersampled frame, averaged down afterwards: modeling::lensFrame). Texture detail
  // finer than a photo's pixels (texture_detail.h) is judged per pixel of that image.
  float supersample = 1.0f;
};

glm::quat orientationFromAxisAngle(const glm::vec4& axisAngle);
glm::vec4 axisAngleFromOrientation(const glm::quat& q);  // angle in [0, pi], axis unit

// Both carry the intrinsics, when there are some, along with the field of view.
Camera cameraFromViewpoint(const Viewpoint& viewpoint);
Viewpoint viewpointFromCamera(const Camera& camera, std::string description);

// The intrinsics a camera has when drawn into a width x height frame. Without
// Camera::intrinsics: fieldOfViewRad across the frame's smaller side (VRML97 6.53),
// the principal point at the frame's centre. With intrinsics for an image of another
// size: that image scaled about its centre onto the frame's centre by the ratio of
// the smaller sides (so the lens sees what its VRML field of view sees, and the
// principal point keeps its offset from the centre in proportion); at the image's own
// size, the intrinsics as they are; with no image size, as they are.
Intrinsics intrinsicsFor(const Camera& camera, int width, int height);

// The field of view (VRML meaning) of intrinsics: the angle across the image's smaller
// side, through the image's centre line (the principal point's offset is not an angle
// VRML97 can say).
float fieldOfViewOf(const Intrinsics& intrinsics);

glm::mat4 viewMatrix(const Camera& camera);  // world to camera
glm::mat4 projectionMatrix(const Camera& camera, int width, int height);  // camera to Vulkan clip

// Pixel position (u, v) of a world point, and its depth in front of the camera in
// metres (negative: behind it).
glm::dvec3 projectToPixel(const Camera& camera, int width, int height, const glm::vec3& world);

// Direction the camera looks in (world), and its up vector.
glm::vec3 forwardOf(const Camera& camera);
glm::vec3 upOf(const Camera& camera);

// Orientation looking from `eye` towards `target` with world +Y up (no roll).
glm::quat lookAtOrientation(const glm::vec3& eye, const glm::vec3& target);

}  // namespace pw::engine
