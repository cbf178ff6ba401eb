// The walking person: where the eye is, where it looks, and how it moves through a
// scene (VRML97 NavigationInfo type WALK): gravity keeps the eye at the avatar's
// height above the ground below, steps up to the step height are climbed, walls stop
// the body at the avatar's radius and it slides along them.
#pragma once

#include <glm/glm.hpp>

#include "engine/scene/camera.h"
#include "engine/scene/collision.h"
#include "engine/scene/scene.h"

namespace pw::walk {

// What the person does during one simulation step.
struct MoveInput {
  double forward = 0;  // -1 .. 1 (S/W, DOWN/UP)
  double strafe = 0;   // -1 .. 1 (A/D, LEFT/RIGHT)
  bool run = false;    // Shift: twice the speed
  double lookDxPx = 0;  // pointer motion since the last step
  double lookDyPx = 0;
};

class Avatar {
 public:
  // `world` may be null (no collision, no gravity); it must outlive the avatar.
  Avatar(const engine::NavigationInfo& navigation, const engine::CollisionWorld* world, double speedScale = 1.0);

  // Puts the eye exactly at the viewpoint, looking its way (roll dropped). Gravity
  // waits until the person next walks, so a viewpoint in the air stays put.
  void placeAt(const engine::Viewpoint& viewpoint);
  void placeAt(const glm::dvec3& eye, double yawRad, double pitchRad);

  void step(double dtS, const MoveInput& input);

  glm::dvec3 eye() const { return eye_; }
  double yawRad() const { return yawRad_; }     // 0 looks along -Z; + turns left
  double pitchRad() const { return pitchRad_; }  // + looks up
  glm::quat orientation() const;
  engine::Camera camera(float fieldOfViewRad) const;
  double speedMps() const { return speedMps_; }

  static constexpr double kLookRadPerPx = 0.0025;
  static constexpr double kMaxPitchRad = 1.48;  // about 85 degrees
  static constexpr double kGravityMps2 = 9.81;

 private:
  glm::dvec3 moveBody(const glm::dvec3& delta) const;
  void applyGravity(double dtS);

  const engine::CollisionWorld* world_;
  double radiusM_, heightM_, stepM_, speedMps_;
  glm::dvec3 eye_{0.0, 1.6, 0.0};
  double yawRad_ = 0, pitchRad_ = 0;
  double fallMps_ = 0;
  bool grounded_ = false;  // gravity is on (the person has walked since the last jump)
};

}  // namespace pw::walk
