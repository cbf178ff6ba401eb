#include "editor/walk/avatar.h"

#include <gtest/gtest.h>

namespace pw::walk {
namespace {

void addQuad(engine::Mesh& m, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
  const uint32_t base = static_cast<uint32_t>(m.positions.size());
  m.positions.insert(m.positions.end(), {a, b, c, d});
  m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}

// A corridor 2 m wide, 3 m high, from z = 2 to the far wall at z = -10, with a
// 0.2 m step up at z < -6.
engine::Scene corridor() {
  auto m = std::make_shared<engine::Mesh>();
  addQuad(*m, {-1, 0, 2}, {1, 0, 2}, {1, 0, -6}, {-1, 0, -6});            // floor
  addQuad(*m, {-1, 0, -6}, {1, 0, -6}, {1, 0.2f, -6}, {-1, 0.2f, -6});    // riser
  addQuad(*m, {-1, 0.2f, -6}, {1, 0.2f, -6}, {1, 0.2f, -10}, {-1, 0.2f, -10});  // upper floor
  addQuad(*m, {-1, 0, -10}, {1, 0, -10}, {1, 3, -10}, {-1, 3, -10});      // far wall
  addQuad(*m, {-1, 0, 2}, {-1, 0, -10}, {-1, 3, -10}, {-1, 3, 2});        // left wall
  addQuad(*m, {1, 0, -10}, {1, 0, 2}, {1, 3, 2}, {1, 3, -10});            // right wall
  engine::Scene scene;
  scene.shapes.push_back({m, nullptr, glm::mat4(1.0f), "corridor"});
  return scene;
}

engine::NavigationInfo navigation() {
  engine::NavigationInfo nav;
  nav.avatarHeightM = 1.6f;
  nav.avatarRadiusM = 0.25f;
  nav.stepHeightM = 0.3f;
  nav.speedMps = 1.5f;
  return nav;
}

TEST(Avatar, WalksForwardAtTheSetSpeed) {
  const engine::Scene scene = corridor();
  const auto world = engine::CollisionWorld::fromScene(scene);
  Avatar avatar(navigation(), &world);
  avatar.placeAt({0, 1.6, 0}, 0, 0);
  for (int i = 0; i < 60; ++i) avatar.step(1.0 / 60, {1, 0});
  EXPECT_NEAR(avatar.eye().z, -1.5, 1e-6);
  EXPECT_NEAR(avatar.eye().y, 1.6, 1e-6);
  EXPECT_NEAR(avatar.eye().x, 0.0, 1e-9);
}

TEST(Avatar, StopsAtTheFarWallEvenAtTenTimesTheSpeed) {
  const engine::Scene scene = corridor();
  const auto world = engine::CollisionWorld::fromScene(scene);
  for (double scale : {1.0, 10.0, 100.0}) {
    Avatar avatar(navigation(), &world, scale);
    avatar.placeAt({0, 1.6, 0}, 0, 0);
    for (int i = 0; i < 600; ++i) {
      avatar.step(1.0 / 60, {1, 0, true});
      ASSERT_GE(avatar.eye().z, -10.0 + 0.25 - 1e-3) << "scale " << scale << " step " << i;
    }
    EXPECT_NEAR(avatar.eye().z, -10.0 + 0.25, 0.01) << "scale " << scale;
  }
}

TEST(Avatar, ClimbsAStepAndKeepsEyeHeight) {
  const engine::Scene scene = corridor();
  const auto world = engine::CollisionWorld::fromScene(scene);
  Avatar avatar(navigation(), &world);
  avatar.placeAt({0, 1.6, -4}, 0, 0);
  for (int i = 0; i < 180; ++i) avatar.step(1.0 / 60, {1, 0});
  EXPECT_LT(avatar.eye().z, -6.5);
  EXPECT_NEAR(avatar.eye().y, 1.8, 1e-5);
}

TEST(Avatar, SlidesAlongAWallWhenWalkingDiagonally) {
  const engine::Scene scene = corridor();
  const auto world = engine::CollisionWorld::fromScene(scene);
  Avatar avatar(navigation(), &world);
  avatar.placeAt({0, 1.6, 0}, glm::radians(45.0), 0);  // facing forward-left
  for (int i = 0; i < 120; ++i) avatar.step(1.0 / 60, {1, 0});
  EXPECT_NEAR(avatar.eye().x, -1.0 + 0.25, 0.01);
  EXPECT_LT(avatar.eye().z, -1.0);
}

TEST(Avatar, FallsToTheFloorOnceWalking) {
  const engine::Scene scene = corridor();
  const auto world = engine::CollisionWorld::fromScene(scene);
  Avatar avatar(navigation(), &world);
  avatar.placeAt({0, 2.5, 0}, 0, 0);
  avatar.step(1.0 / 60, {});
  EXPECT_NEAR(avatar.eye().y, 2.5, 1e-9);  // a viewpoint in the air stays until one walks
  for (int i = 0; i < 120; ++i) avatar.step(1.0 / 60, {0.01, 0});
  EXPECT_NEAR(avatar.eye().y, 1.6, 1e-6);
}

TEST(Avatar, MouseLooksAroundAndPitchIsClamped) {
  Avatar avatar(navigation(), nullptr);
  avatar.placeAt({0, 1.6, 0}, 0, 0);
  avatar.step(1.0 / 60, {0, 0, false, 100, -10000});
  EXPECT_NEAR(avatar.yawRad(), -100 * Avatar::kLookRadPerPx, 1e-12);
  EXPECT_NEAR(avatar.pitchRad(), Avatar::kMaxPitchRad, 1e-12);
}

TEST(Avatar, PlaceAtViewpointTakesItsPositionAndHeading) {
  Avatar avatar(navigation(), nullptr);
  engine::Viewpoint vp;
  vp.position = {1, 2, 3};
  vp.orientation = {0, 1, 0, 3.14159265f};  // looking along +Z
  avatar.placeAt(vp);
  EXPECT_EQ(avatar.eye(), glm::dvec3(1, 2, 3));
  const glm::vec3 f = engine::forwardOf(avatar.camera(1.0f));
  EXPECT_NEAR(f.z, 1.0f, 1e-5f);
}

}  // namespace
}  // namespace pw::walk
