#include "engine/gpu/frustum.h"

#include <gtest/gtest.h>

#include "engine/scene/camera.h"

namespace pw::engine::gpu {
namespace {

Bounds box(glm::vec3 centre, float half) {
  Bounds b;
  b.add(centre - glm::vec3(half));
  b.add(centre + glm::vec3(half));
  return b;
}

class FrustumTest : public ::testing::Test {
 protected:
  void SetUp() override {
    camera_.position = {0, 0, 0};  // looking down -Z
    camera_.fieldOfViewRad = 1.0f;
    camera_.nearM = 0.1f;
    camera_.farM = 100.0f;
    frustum_ = frustumFromViewProjection(projectionMatrix(camera_, 200, 100) * viewMatrix(camera_));
  }
  Camera camera_;
  Frustum frustum_;
};

TEST_F(FrustumTest, BoxAheadIsInside) { EXPECT_TRUE(intersects(frustum_, box({0, 0, -10}, 1))); }
TEST_F(FrustumTest, BoxBehindIsOutside) { EXPECT_FALSE(intersects(frustum_, box({0, 0, 10}, 1))); }
TEST_F(FrustumTest, BoxBeyondFarIsOutside) { EXPECT_FALSE(intersects(frustum_, box({0, 0, -110}, 1))); }
TEST_F(FrustumTest, BoxFarToTheSideIsOutside) {
  EXPECT_FALSE(intersects(frustum_, box({-40, 0, -10}, 1)));
  EXPECT_FALSE(intersects(frustum_, box({0, 40, -10}, 1)));
}
TEST_F(FrustumTest, BoxStraddlingAnEdgeIsInside) {
  // The frame is 2:1, fov 1 rad vertically: the right edge at depth 10 is x = 10 tan(0.5) * 2 = 10.9.
  EXPECT_TRUE(intersects(frustum_, box({11.5f, 0, -10}, 1)));
  EXPECT_FALSE(intersects(frustum_, box({13.5f, 0, -10}, 1)));
}
TEST_F(FrustumTest, EmptyBoundsAreNeverVisible) { EXPECT_FALSE(intersects(frustum_, Bounds{})); }
TEST_F(FrustumTest, CameraInsideTheBoxSeesIt) { EXPECT_TRUE(intersects(frustum_, box({0, 0, 0}, 5))); }

}  // namespace
}  // namespace pw::engine::gpu
