#include "engine/scene/camera.h"

#include <cmath>

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

namespace pw::engine {
namespace {

TEST(Camera, IdentityLooksDownMinusZ) {
  Camera camera;
  EXPECT_NEAR(forwardOf(camera).z, -1.0f, 1e-6f);
  EXPECT_NEAR(upOf(camera).y, 1.0f, 1e-6f);
}

TEST(Camera, PointOnAxisProjectsToPrincipalPoint) {
  Camera camera;
  const glm::dvec3 p = projectToPixel(camera, 640, 480, glm::vec3(0, 0, -5));
  EXPECT_NEAR(p.x, 319.5, 1e-9);
  EXPECT_NEAR(p.y, 239.5, 1e-9);
  EXPECT_NEAR(p.z, 5.0, 1e-6);
}

TEST(Camera, FieldOfViewSpansTheSmallerSide) {
  Camera camera;
  camera.fieldOfViewRad = glm::half_pi<float>();  // 90 degrees: edge at x = depth
  // 640x480: the vertical angle is the field of view; the top edge of the frame is
  // half a pixel above the top pixel centre.
  const glm::dvec3 top = projectToPixel(camera, 640, 480, glm::vec3(0, 5, -5));
  EXPECT_NEAR(top.y, 239.5 - 240.0, 1e-4);
  // 480x640 (portrait): the horizontal angle is.
  const glm::dvec3 right = projectToPixel(camera, 480, 640, glm::vec3(5, 0, -5));
  EXPECT_NEAR(right.x, 239.5 + 240.0, 1e-4);
}

TEST(Camera, ProjectionMatrixAgreesWithPixelProjection) {
  Camera camera;
  camera.position = {1, 2, 3};
  camera.orientation = orientationFromAxisAngle({0.3f, 1.0f, 0.1f, 0.7f});
  camera.intrinsics = Intrinsics{700, 710, 301.25, 222.5};
  const int w = 640, h = 480;
  const glm::vec3 world = camera.position + forwardOf(camera) * 4.0f + glm::vec3(0.3f, -0.2f, 0.1f);
  const glm::vec4 clip = projectionMatrix(camera, w, h) * viewMatrix(camera) * glm::vec4(world, 1.0f);
  const glm::dvec3 ndc = glm::dvec3(clip) / double(clip.w);
  // Vulkan viewport: pixel edge coordinate = (ndc + 1) / 2 * size; centre convention: minus 0.5.
  const glm::dvec3 pixel = projectToPixel(camera, w, h, world);
  EXPECT_NEAR((ndc.x + 1) * 0.5 * w - 0.5, pixel.x, 1e-3);
  EXPECT_NEAR((ndc.y + 1) * 0.5 * h - 0.5, pixel.y, 1e-3);
  EXPECT_GT(ndc.z, 0.0);
  EXPECT_LT(ndc.z, 1.0);
}

// A photo's intrinsics drawn at the photo's size are used as they are; at another size
// the photo is scaled about its centre by the ratio of the smaller sides, so a point
// keeps its place relative to the image (here: half the frame, and a wider frame).
TEST(Camera, PhotoIntrinsicsFitFramesOfOtherSizes) {
  Camera camera;
  camera.intrinsics = Intrinsics{760, 760, 541.5, 360, 1024, 768};
  camera.fieldOfViewRad = 0.3f;  // ignored with intrinsics
  const glm::vec3 world(0.4f, -0.3f, -3.0f);
  const glm::dvec3 full = projectToPixel(camera, 1024, 768, world);
  EXPECT_NEAR(full.x, 541.5 + 760 * 0.4 / 3.0, 1e-4);
  EXPECT_NEAR(full.y, 360 + 760 * 0.3 / 3.0, 1e-4);
  EXPECT_EQ(intrinsicsFor(camera, 1024, 768), *camera.intrinsics);
  // Half size: pixel edges scale by 1/2 ((u + 0.5) / 2 - 0.5).
  const glm::dvec3 half = projectToPixel(camera, 512, 384, world);
  EXPECT_NEAR(half.x, (full.x + 0.5) / 2 - 0.5, 1e-4);
  EXPECT_NEAR(half.y, (full.y + 0.5) / 2 - 0.5, 1e-4);
  // 1280 x 768: the same scale (the smaller sides agree), 128 px more on each side.
  const glm::dvec3 wide = projectToPixel(camera, 1280, 768, world);
  EXPECT_NEAR(wide.x, full.x + 128, 1e-4);
  EXPECT_NEAR(wide.y, full.y, 1e-4);
  // Its field of view is the one across the smaller side.
  EXPECT_NEAR(fieldOfViewOf(*camera.intrinsics), 2 * std::atan(384.0 / 760.0), 1e-6);
  // A viewpoint carries them.
  const Camera back = cameraFromViewpoint(viewpointFromCamera(camera, "Photo"));
  EXPECT_EQ(back.intrinsics, camera.intrinsics);
}

TEST(Camera, DepthRangeIsZeroToOne) {
  Camera camera;
  camera.nearM = 0.1f;
  camera.farM = 100.0f;
  const glm::mat4 p = projectionMatrix(camera, 100, 100);
  const glm::vec4 nearClip = p * glm::vec4(0, 0, -0.1f, 1);
  const glm::vec4 farClip = p * glm::vec4(0, 0, -100.0f, 1);
  EXPECT_NEAR(nearClip.z / nearClip.w, 0.0f, 1e-5f);
  EXPECT_NEAR(farClip.z / farClip.w, 1.0f, 1e-5f);
}

TEST(Camera, AxisAngleRoundTrip) {
  const glm::vec4 aa(glm::normalize(glm::vec3(0.2f, -0.9f, 0.4f)), 2.1f);
  const glm::vec4 back = axisAngleFromOrientation(orientationFromAxisAngle(aa));
  EXPECT_NEAR(back.x, aa.x, 1e-5f);
  EXPECT_NEAR(back.y, aa.y, 1e-5f);
  EXPECT_NEAR(back.z, aa.z, 1e-5f);
  EXPECT_NEAR(back.w, aa.w, 1e-5f);
}

TEST(Camera, ZeroAxisIsIdentityNotNaN) {
  const glm::quat q = orientationFromAxisAngle({0, 0, 0, 1.0f});
  EXPECT_EQ(q, glm::quat(1, 0, 0, 0));
}

TEST(Camera, LookAtFacesTheTarget) {
  Camera camera;
  camera.position = {0, 1.6f, 0};
  camera.orientation = lookAtOrientation(camera.position, {3, 1.6f, -4});
  const glm::vec3 f = forwardOf(camera);
  EXPECT_NEAR(f.x, 0.6f, 1e-5f);
  EXPECT_NEAR(f.z, -0.8f, 1e-5f);
  EXPECT_NEAR(upOf(camera).y, 1.0f, 1e-5f);
}

}  // namespace
}  // namespace pw::engine
