#include "engine/scene/scene.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

namespace pw::engine {
namespace {

Mesh unitQuad() {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

TEST(Scene, BoundsOfTransformedShape) {
  Shape shape;
  shape.mesh = std::make_shared<Mesh>(unitQuad());
  shape.transform = glm::translate(glm::mat4(1.0f), glm::vec3(2, 0, -1)) * glm::scale(glm::mat4(1.0f), glm::vec3(3));
  const Bounds b = worldBounds(shape);
  EXPECT_FLOAT_EQ(b.min.x, 2.0f);
  EXPECT_FLOAT_EQ(b.max.x, 5.0f);
  EXPECT_FLOAT_EQ(b.max.y, 3.0f);
  EXPECT_FLOAT_EQ(b.min.z, -1.0f);
}

TEST(Scene, EmptySceneHasEmptyBounds) {
  Scene scene;
  EXPECT_TRUE(sceneBounds(scene).empty());
  scene.shapes.push_back(Shape{});  // a shape with no mesh adds nothing
  EXPECT_TRUE(sceneBounds(scene).empty());
}

TEST(Scene, SmoothNormalsOfAFlatQuadFaceItsFront) {
  Mesh m = unitQuad();
  computeSmoothNormals(m);
  ASSERT_EQ(m.normals.size(), 4u);
  for (const glm::vec3& n : m.normals) EXPECT_NEAR(n.z, 1.0f, 1e-6f);
}

TEST(Scene, DefaultViewpointSeesEverything) {
  Scene scene;
  Shape s;
  s.mesh = std::make_shared<Mesh>(unitQuad());
  scene.shapes.push_back(s);
  const Viewpoint v = defaultViewpoint(scene);
  EXPECT_NEAR(v.position.x, 0.5f, 1e-6f);
  EXPECT_GT(v.position.z, 1.0f);
}

}  // namespace
}  // namespace pw::engine
