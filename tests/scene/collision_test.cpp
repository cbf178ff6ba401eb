#include "engine/scene/collision.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace pw::engine {
namespace {

// A zero-thickness wall: the quad x in [-5, 5], y in [0, 3] at z = -2.
Scene wallScene() {
  auto mesh = std::make_shared<Mesh>();
  mesh->positions = {{-5, 0, -2}, {5, 0, -2}, {5, 3, -2}, {-5, 3, -2}};
  mesh->indices = {0, 1, 2, 0, 2, 3};
  Scene scene;
  scene.shapes.push_back(Shape{mesh, nullptr, glm::mat4(1.0f), "wall"});
  return scene;
}

TEST(Collision, RayHitsWallAtItsDistance) {
  const CollisionWorld world = CollisionWorld::fromScene(wallScene());
  auto hit = world.raycast({0, 1, 0}, {0, 0, -1}, 100);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->distance, 2.0f, 1e-5f);
  EXPECT_NEAR(hit->normal.z, 1.0f, 1e-5f);
}

TEST(Collision, RayPassesBesideWall) {
  const CollisionWorld world = CollisionWorld::fromScene(wallScene());
  EXPECT_FALSE(world.raycast({6, 1, 0}, {0, 0, -1}, 100));
  EXPECT_FALSE(world.raycast({0, 1, 0}, {0, 0, -1}, 1.5f));  // stops short
}

TEST(Collision, SphereStopsAtRadiusEvenWhenFast) {
  const CollisionWorld world = CollisionWorld::fromScene(wallScene());
  for (float speed : {0.1f, 1.0f, 50.0f, 1000.0f}) {
    const glm::vec3 end = world.slideSphere({0, 1, 0}, 0.25f, {0, 0, -speed});
    // It goes all the way, or to the wall less its radius (resolvePenetration leaves
    // 1e-4 m of clearance), and nowhere else: the 8000 sub-steps at speed 1000 drift
    // sideways by 9e-5 m in float.
    EXPECT_NEAR(end.z, std::max(-speed, -2.0f + 0.25f), 1e-3f) << "speed " << speed;
    EXPECT_NEAR(end.x, 0.0f, 1e-3f) << "speed " << speed;
    EXPECT_NEAR(end.y, 1.0f, 1e-3f) << "speed " << speed;
  }
}

TEST(Collision, SphereSlidesAlongWall) {
  const CollisionWorld world = CollisionWorld::fromScene(wallScene());
  const glm::vec3 end = world.slideSphere({0, 1, -1.5f}, 0.25f, {1, 0, -1});
  // The whole step along the wall, none of it into the wall: stopped at its radius.
  EXPECT_NEAR(end.x, 1.0f, 0.05f);
  EXPECT_NEAR(end.y, 1.0f, 1e-3f);
  EXPECT_NEAR(end.z, -1.75f, 1e-3f);
}

TEST(Collision, ManyTrianglesBuildABalancedTree) {
  Scene scene;
  auto mesh = std::make_shared<Mesh>();
  for (int i = 0; i < 1000; ++i) {
    const float x = static_cast<float>(i);
    const uint32_t base = static_cast<uint32_t>(mesh->positions.size());
    mesh->positions.insert(mesh->positions.end(), {{x, 0, 0}, {x + 0.5f, 0, 0}, {x, 1, 0}});
    mesh->indices.insert(mesh->indices.end(), {base, base + 1, base + 2});
  }
  scene.shapes.push_back(Shape{mesh, nullptr, glm::mat4(1.0f), ""});
  const CollisionWorld world = CollisionWorld::fromScene(scene);
  EXPECT_EQ(world.triangleCount(), 1000u);
  auto hit = world.raycast({700.1f, 0.2f, 5}, {0, 0, -1}, 10);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->distance, 5.0f, 1e-4f);
  // Median splits: 250 leaves of 3-4 triangles, 8 splits deep below the root, the
  // least a tree of leaves of at most 4 can be (ceil(log2(1000 / 4)) + 1 = 9 levels).
  // A lopsided split (one triangle off per level) would be hundreds deep and overflow
  // the traversals' 64-entry stacks.
  const CollisionWorld::TreeStats tree = world.treeStats();
  EXPECT_EQ(tree.depth, 9u);
  EXPECT_LE(tree.largestLeaf, 4u);
  EXPECT_EQ(tree.leafTriangles, 1000u);
  EXPECT_EQ(tree.nodes, 2 * tree.leaves - 1);
  EXPECT_GE(tree.leaves, 250u);
  EXPECT_LE(tree.leaves, 256u);
}

}  // namespace
}  // namespace pw::engine
