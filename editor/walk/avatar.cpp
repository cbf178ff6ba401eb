#include "editor/walk/avatar.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/quaternion.hpp>

namespace pw::walk {

Avatar::Avatar(const engine::NavigationInfo& navigation, const engine::CollisionWorld* world, double speedScale)
    : world_(world),
      radiusM_(std::max(0.05f, navigation.avatarRadiusM)),
      heightM_(std::max(0.1f, navigation.avatarHeightM)),
      stepM_(std::max(0.0f, navigation.stepHeightM)),
      speedMps_(std::max(0.01, static_cast<double>(navigation.speedMps)) * speedScale) {}

void Avatar::placeAt(const glm::dvec3& eye, double yawRad, double pitchRad) {
  eye_ = eye;
  yawRad_ = yawRad;
  pitchRad_ = std::clamp(pitchRad, -kMaxPitchRad, kMaxPitchRad);
  fallMps_ = 0;
  grounded_ = false;
}

void Avatar::placeAt(const engine::Viewpoint& viewpoint) {
  const glm::dquat q(engine::orientationFromAxisAngle(viewpoint.orientation));
  const glm::dvec3 forward = q * glm::dvec3(0, 0, -1);
  const double yaw = std::atan2(-forward.x, -forward.z);
  const double pitch = std::asin(std::clamp(forward.y, -1.0, 1.0));
  placeAt(glm::dvec3(viewpoint.position), yaw, pitch);
}

glm::quat Avatar::orientation() const {
  return glm::quat(glm::angleAxis(yawRad_, glm::dvec3(0, 1, 0)) * glm::angleAxis(pitchRad_, glm::dvec3(1, 0, 0)));
}

engine::Camera Avatar::camera(float fieldOfViewRad) const {
  engine::Camera camera;
  camera.position = glm::vec3(eye_);
  camera.orientation = orientation();
  camera.fieldOfViewRad = fieldOfViewRad;
  camera.nearM = static_cast<float>(std::min(0.05, 0.5 * radiusM_));
  return camera;
}

// The body is a column of spheres from just above the highest step to the eye, so
// that steps are climbed (by gravity) and everything higher stops the person.
glm::dvec3 Avatar::moveBody(const glm::dvec3& delta) const {
  if (!world_) return delta;
  const double feet = eye_.y - heightM_;
  const double lowest = feet + stepM_ + radiusM_;
  const double highest = eye_.y;
  std::vector<double> heights{lowest};
  for (double h = lowest + 1.5 * radiusM_; h < highest; h += 1.5 * radiusM_) heights.push_back(h);
  if (highest > lowest) heights.push_back(highest);
  glm::dvec3 allowed = delta;
  // Each sphere may only shorten or bend the move: run them in turn on the move the
  // previous ones allowed, twice so the last sphere's correction reaches the first.
  for (int pass = 0; pass < 2; ++pass) {
    for (double h : heights) {
      const glm::vec3 start(eye_.x, h, eye_.z);
      const glm::vec3 end = world_->slideSphere(start, static_cast<float>(radiusM_), glm::vec3(allowed));
      allowed = glm::dvec3(end - start);
      allowed.y = 0;
    }
  }
  return allowed;
}

void Avatar::applyGravity(double dtS) {
  if (!world_ || !grounded_) return;
  // Ground: the highest surface below the eye and no higher than a step above the feet.
  const glm::vec3 from(eye_.x, eye_.y - heightM_ + stepM_ + 1e-3, eye_.z);
  auto hit = world_->raycast(from, {0, -1, 0}, 1000.0f);
  if (!hit) return;  // nothing below: hover, as over an unfinished model
  const double target = hit->point.y + heightM_;
  if (eye_.y <= target) {  // on the ground or climbing a step
    eye_.y = target;
    fallMps_ = 0;
    return;
  }
  fallMps_ += kGravityMps2 * dtS;
  eye_.y = std::max(target, eye_.y - fallMps_ * dtS);
  if (eye_.y == target) fallMps_ = 0;
}

void Avatar::step(double dtS, const MoveInput& input) {
  yawRad_ -= input.lookDxPx * kLookRadPerPx;
  pitchRad_ = std::clamp(pitchRad_ - input.lookDyPx * kLookRadPerPx, -kMaxPitchRad, kMaxPitchRad);
  const double forward = std::clamp(input.forward, -1.0, 1.0), strafe = std::clamp(input.strafe, -1.0, 1.0);
  if (forward != 0 || strafe != 0) {
    grounded_ = true;
    const glm::dvec3 ahead(-std::sin(yawRad_), 0, -std::cos(yawRad_));
    const glm::dvec3 right(std::cos(yawRad_), 0, -std::sin(yawRad_));
    glm::dvec3 direction = ahead * forward + right * strafe;
    if (glm::length(direction) > 1.0) direction = glm::normalize(direction);
    const double speed = speedMps_ * (input.run ? 2.0 : 1.0);
    eye_ += moveBody(direction * speed * dtS);
  }
  applyGravity(dtS);
}

}  // namespace pw::walk
