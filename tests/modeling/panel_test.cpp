#include "modeling/panel.h"

#include <gtest/gtest.h>

#include "modeling/surfaces.h"
#include "engine/scene/collision.h"

namespace pw::modeling {
namespace {

double area(const engine::Mesh& m) {
  double a = 0;
  for (size_t i = 0; i + 2 < m.indices.size(); i += 3) {
    const glm::dvec3 p0 = m.positions[m.indices[i]], p1 = m.positions[m.indices[i + 1]], p2 = m.positions[m.indices[i + 2]];
    a += 0.5 * glm::length(glm::cross(p1 - p0, p2 - p0));
  }
  return a;
}

TEST(Panel, PlainPanelIsTwoTrianglesFacingItsFront) {
  Panel p = surfacePanel(Surface::kFloor, {2, 3, 10});
  const engine::Mesh m = panelMesh(p);
  EXPECT_EQ(m.indices.size(), 6u);
  EXPECT_NEAR(area(m), 20.0, 1e-5);
  const glm::vec3 a = m.positions[m.indices[0]], b = m.positions[m.indices[1]], c = m.positions[m.indices[2]];
  EXPECT_GT(glm::cross(b - a, c - a).y, 0.0f);  // the floor faces up, into the corridor
}

TEST(Panel, EverySurfaceFacesIntoTheCorridor) {
  const metrology::Dimensions box{2, 3, 10};
  const glm::dvec3 inside(0, 1.5, -5);
  for (int i = 0; i < kSurfaceCount; ++i) {
    const Panel p = surfacePanel(static_cast<Surface>(i), box, 1.0);
    const glm::dvec3 centre = p.point(0.5 * (p.extent.s0 + p.extent.s1), 0.5 * (p.extent.t0 + p.extent.t1));
    EXPECT_GT(glm::dot(p.normal(), inside - centre), 0.0) << surfaceName(static_cast<Surface>(i));
  }
}

TEST(Panel, OpeningRemovesItsAreaAndKeepsTexture) {
  Panel p = surfacePanel(Surface::kLeftWall, {2, 3, 10});
  p.textureRect = p.extent;
  p.openings.push_back({4, 0, 6, 2.5});
  const engine::Mesh m = panelMesh(p);
  EXPECT_NEAR(area(m), 30.0 - 5.0, 1e-4);
  // A vertex at s = 4 (z = -4), t = 2.5 has u = 0.4, v = 2.5 / 3.
  bool found = false;
  for (size_t i = 0; i < m.positions.size(); ++i) {
    if (std::abs(m.positions[i].z + 4) < 1e-5 && std::abs(m.positions[i].y - 2.5f) < 1e-5) {
      found = true;
      EXPECT_NEAR(m.texCoords[i].x, 0.4f, 1e-6f);
      EXPECT_NEAR(m.texCoords[i].y, 2.5f / 3.0f, 1e-6f);
    }
  }
  EXPECT_TRUE(found);
}

TEST(Panel, RayThroughOpeningIsNotBlocked) {
  Panel p = surfacePanel(Surface::kFarWall, {2, 3, 10});
  p.openings.push_back({0.5, 0, 1.5, 2.0});
  engine::Scene scene;
  scene.shapes.push_back({std::make_shared<engine::Mesh>(panelMesh(p)), nullptr, glm::mat4(1.0f), "far"});
  const auto world = engine::CollisionWorld::fromScene(scene);
  EXPECT_FALSE(world.raycast({0, 1, 0}, {0, 0, -1}, 20));      // through the opening
  EXPECT_TRUE(world.raycast({0, 2.5f, 0}, {0, 0, -1}, 20));    // above it: the lintel
  EXPECT_TRUE(world.raycast({0.8f, 1, 0}, {0, 0, -1}, 20));    // beside it
}

}  // namespace
}  // namespace pw::modeling
