#include "engine/scene/camera.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace pw::engine {

glm::quat orientationFromAxisAngle(const glm::vec4& axisAngle) {
  glm::vec3 axis(axisAngle);
  const float len = glm::length(axis);
  if (!(len > 1e-12f) || !std::isfinite(axisAngle.w)) return glm::quat(1, 0, 0, 0);
  return glm::angleAxis(axisAngle.w, axis / len);
}

glm::vec4 axisAngleFromOrientation(const glm::quat& qIn) {
  glm::quat q = glm::normalize(qIn);
  if (q.w < 0) q = -q;
  const float s = std::sqrt(std::max(0.0f, 1.0f - q.w * q.w));
  if (s < 1e-7f) return {0, 0, 1, 0};
  return {q.x / s, q.y / s, q.z / s, 2.0f * std::acos(std::min(1.0f, q.w))};
}

Camera cameraFromViewpoint(const Viewpoint& viewpoint) {
  Camera camera;
  camera.position = viewpoint.position;
  camera.orientation = orientationFromAxisAngle(viewpoint.orientation);
  camera.fieldOfViewRad = viewpoint.fieldOfViewRad;
  camera.intrinsics = viewpoint.intrinsics;
  return camera;
}

Viewpoint viewpointFromCamera(const Camera& camera, std::string description) {
  Viewpoint v;
  v.description = std::move(description);
  v.position = camera.position;
  v.orientation = axisAngleFromOrientation(camera.orientation);
  v.fieldOfViewRad = camera.fieldOfViewRad;
  v.intrinsics = camera.intrinsics;
  return v;
}

Intrinsics intrinsicsFor(const Camera& camera, int width, int height) {
  if (camera.intrinsics) {
    Intrinsics k = *camera.intrinsics;
    if (k.imageWidth <= 0 || k.imageHeight <= 0 || (k.imageWidth == width && k.imageHeight == height)) return k;
    // Pixel edges: the image's centre (w/2, h/2) lands on the frame's, scaled by s.
    const double s = static_cast<double>(std::min(width, height)) / std::min(k.imageWidth, k.imageHeight);
    k.focalXPx *= s;
    k.focalYPx *= s;
    k.principalU = 0.5 * width - 0.5 + s * (k.principalU + 0.5 - 0.5 * k.imageWidth);
    k.principalV = 0.5 * height - 0.5 + s * (k.principalV + 0.5 - 0.5 * k.imageHeight);
    k.imageWidth = width;
    k.imageHeight = height;
    return k;
  }
  // VRML97 6.53: fieldOfView is the angle across the smaller dimension.
  const double halfTan = std::tan(std::clamp(camera.fieldOfViewRad, 1e-4f, 3.1f) * 0.5);
  const double focal = 0.5 * std::min(width, height) / halfTan;
  return {focal, focal, (width - 1) * 0.5, (height - 1) * 0.5, width, height};
}

float fieldOfViewOf(const Intrinsics& k) {
  const bool wide = k.imageWidth >= k.imageHeight;
  const double side = wide ? k.imageHeight : k.imageWidth;
  const double focal = wide ? k.focalYPx : k.focalXPx;
  return static_cast<float>(2.0 * std::atan(0.5 * side / focal));
}

glm::mat4 viewMatrix(const Camera& camera) {
  const glm::mat4 rotation = glm::mat4_cast(glm::conjugate(glm::normalize(camera.orientation)));
  return rotation * glm::translate(glm::mat4(1.0f), -camera.position);
}

glm::mat4 projectionMatrix(const Camera& camera, int width, int height) {
  const Intrinsics k = intrinsicsFor(camera, width, height);
  const double n = camera.nearM, f = camera.farM;
  // Camera space looks down -Z; with w = -z:
  //   u = fx x / w + cu  ->  x_ndc = (2u + 1) / W - 1   (pixel centre u sits at u + 0.5)
  //   v = cv - fy y / w  ->  y_ndc = (2v + 1) / H - 1   (Vulkan: y_ndc = -1 at the top)
  glm::dmat4 p(0.0);
  p[0][0] = 2.0 * k.focalXPx / width;
  p[2][0] = -((2.0 * k.principalU + 1.0) / width - 1.0);
  p[1][1] = -2.0 * k.focalYPx / height;
  p[2][1] = -((2.0 * k.principalV + 1.0) / height - 1.0);
  p[2][2] = -f / (f - n);
  p[3][2] = -f * n / (f - n);
  p[2][3] = -1.0;
  return glm::mat4(p);
}

glm::dvec3 projectToPixel(const Camera& camera, int width, int height, const glm::vec3& world) {
  const Intrinsics k = intrinsicsFor(camera, width, height);
  const glm::dvec3 c = glm::dvec3(viewMatrix(camera) * glm::vec4(world, 1.0f));
  const double depth = -c.z;
  return {k.principalU + k.focalXPx * c.x / depth, k.principalV - k.focalYPx * c.y / depth, depth};
}

glm::vec3 forwardOf(const Camera& camera) { return glm::normalize(camera.orientation) * glm::vec3(0, 0, -1); }
glm::vec3 upOf(const Camera& camera) { return glm::normalize(camera.orientation) * glm::vec3(0, 1, 0); }

glm::quat lookAtOrientation(const glm::vec3& eye, const glm::vec3& target) {
  const glm::vec3 forward = glm::normalize(target - eye);
  glm::vec3 up(0, 1, 0);
  if (std::abs(glm::dot(forward, up)) > 0.999f) up = glm::vec3(0, 0, -1);
  const glm::vec3 right = glm::normalize(glm::cross(forward, up));
  const glm::vec3 trueUp = glm::cross(right, forward);
  return glm::quat_cast(glm::mat3(right, trueUp, -forward));
}

}  // namespace pw::engine
