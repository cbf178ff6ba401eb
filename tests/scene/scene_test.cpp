#include "engine/scene/scene.h"

#include <gtest/gtest.h>

#include <algorithm>

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

TEST(SubdivideTriangles, CutsEachTriangleIntoKSquaredKeepingEdgesAndAttributes) {
  Mesh quad;
  quad.positions = {{0, 0, 0}, {3, 0, 0}, {3, 3, 0}, {0, 3, 0}};
  quad.normals.assign(4, glm::vec3(0, 0, 1));
  quad.texCoords = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  quad.indices = {0, 1, 2, 0, 2, 3};
  const Mesh cut = subdivideTriangles(quad, 3);
  ASSERT_EQ(cut.indices.size(), 2u * 9u * 3u);
  ASSERT_EQ(cut.texCoords.size(), cut.positions.size());
  // Same total area, same winding (every small triangle faces +Z).
  float area = 0;
  for (size_t t = 0; t < cut.indices.size(); t += 3) {
    const glm::vec3 a = cut.positions[cut.indices[t]], b = cut.positions[cut.indices[t + 1]], c = cut.positions[cut.indices[t + 2]];
    const glm::vec3 n = glm::cross(b - a, c - a);
    EXPECT_GT(n.z, 0.0f);
    area += 0.5f * n.z;
  }
  EXPECT_NEAR(area, 9.0f, 1e-4f);
  // Texture coordinates follow positions (the map is affine on this quad).
  for (size_t v = 0; v < cut.positions.size(); ++v) {
    EXPECT_NEAR(cut.texCoords[v].x, cut.positions[v].x / 3.0f, 1e-6f);
    EXPECT_NEAR(cut.texCoords[v].y, cut.positions[v].y / 3.0f, 1e-6f);
  }
  // Points on the shared diagonal come out bit for bit the same from both triangles.
  std::vector<glm::vec3> diagonal;
  for (const glm::vec3& p : cut.positions) {
    if (std::abs(p.x - p.y) < 1e-5f) diagonal.push_back(p);
  }
  ASSERT_EQ(diagonal.size(), 8u);  // 4 points, from each of the two triangles
  for (const glm::vec3& p : diagonal) {
    EXPECT_EQ(std::count(diagonal.begin(), diagonal.end(), p), 2) << p.x;
  }
  EXPECT_EQ(subdivideTriangles(quad, 1), quad);
}

}  // namespace
}  // namespace pw::engine
