#include "engine/gpu/scene_packing.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "engine/scene/color_space.h"
#include "engine/scene/sample_scene.h"

namespace pw::engine::gpu {
namespace {

std::shared_ptr<Mesh> triangle() {
  auto mesh = std::make_shared<Mesh>();
  mesh->positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh->normals.assign(3, glm::vec3(0, 0, 1));
  mesh->indices = {0, 1, 2};
  return mesh;
}

Shape shapeOf(std::shared_ptr<const Mesh> mesh, std::optional<Material> material = Material{}) {
  Shape s;
  s.mesh = std::move(mesh);
  auto a = std::make_shared<Appearance>();
  a->material = material;
  s.appearance = a;
  return s;
}

TEST(SrgbTransfer, RoundTripsAndHitsKnownValues) {
  EXPECT_NEAR(srgbToLinear(0.5f), 0.21404f, 1e-5f);
  EXPECT_NEAR(linearToSrgb(0.21404f), 0.5f, 1e-5f);
  EXPECT_FLOAT_EQ(srgbToLinear(0.0f), 0.0f);
  EXPECT_FLOAT_EQ(srgbToLinear(1.0f), 1.0f);
  for (int i = 0; i <= 255; ++i) {
    const float v = float(i) / 255.0f;
    EXPECT_NEAR(linearToSrgb(srgbToLinear(v)), v, 1e-5f);
  }
}

// Textures cut from a photo get their own pipeline (the footprint-aware filter) and
// push their homography, taken to the shader's v = 1 - t, with the texture's size.
TEST(PackScene, PhotoTexturesGetTheFootprintPipelineAndTheirHomography) {
  auto image = std::make_shared<Image>();
  image->width = 4;
  image->height = 2;
  image->rgba.assign(4 * 2 * 4, 255);
  auto photo = std::make_shared<Texture>();
  photo->image = image;
  photo->sourceFromTexCoord = glm::mat3(glm::vec3(100, 0, 0), glm::vec3(0, 50, 0), glm::vec3(10, 20, 1));
  auto plain = std::make_shared<Texture>();
  plain->image = image;
  Scene scene;
  for (const auto& texture : {photo, plain}) {
    Shape shape = shapeOf(triangle(), std::nullopt);
    auto appearance = std::make_shared<Appearance>();
    appearance->texture = texture;
    shape.appearance = appearance;
    scene.shapes.push_back(shape);
  }
  auto packed = packScene(scene);
  ASSERT_TRUE(packed.ok()) << packed.message();
  ASSERT_EQ(packed->opaque.size(), 2u);
  const DrawItem& a = packed->opaque[0].shapeIndex == 0 ? packed->opaque[0] : packed->opaque[1];
  const DrawItem& b = packed->opaque[0].shapeIndex == 0 ? packed->opaque[1] : packed->opaque[0];
  EXPECT_TRUE(a.variant.photoTexture);
  EXPECT_FALSE(b.variant.photoTexture);
  EXPECT_NE(a.variant.index(), b.variant.index());
  // (u, v) = (0.5, 0.25) is (s, t) = (0.5, 0.75): photo pixel (60, 57.5).
  const glm::mat3 h(glm::vec3(a.textureSource[0]), glm::vec3(a.textureSource[1]), glm::vec3(a.textureSource[2]));
  const glm::vec3 p = h * glm::vec3(0.5f, 0.25f, 1.0f);
  EXPECT_FLOAT_EQ(p.x / p.z, 60.0f);
  EXPECT_FLOAT_EQ(p.y / p.z, 57.5f);
  EXPECT_EQ(a.textureSource[1].w, 4.0f);
  EXPECT_EQ(a.textureSource[2].w, 2.0f);
  EXPECT_EQ(b.textureSource[0], glm::vec4(0.0f));

  // A homography that puts part of the texture behind the camera (w < 0 at a corner),
  // as a damaged file might: drawn as an ordinary texture.
  photo->sourceFromTexCoord = glm::mat3(glm::vec3(100, 0, 1), glm::vec3(0, 50, 0), glm::vec3(10, 20, -0.5f));
  auto damaged = packScene(scene);
  ASSERT_TRUE(damaged.ok()) << damaged.message();
  for (const DrawItem& d : damaged->opaque) EXPECT_FALSE(d.variant.photoTexture);
}

// A point or spot light reaches only the shapes its radius meets (VRML97 6.36):
// each lit draw carries its own list; directional lights reach everything.
TEST(PackScene, LitDrawsListTheLightsWithinReach) {
  Scene scene;
  scene.shapes.push_back(shapeOf(triangle()));
  Shape far = shapeOf(triangle());
  far.transform = glm::translate(glm::mat4(1.0f), glm::vec3(50, 0, 0));
  scene.shapes.push_back(far);
  scene.shapes.push_back(shapeOf(triangle(), std::nullopt));  // unlit: no lights at all
  Light sun;
  sun.type = LightType::kDirectional;
  Light lamp;
  lamp.type = LightType::kPoint;
  lamp.position = {0, 0, 3};
  lamp.radius = 5;
  Light spot;
  spot.type = LightType::kSpot;
  spot.position = {52, 0, 0};
  spot.radius = 4;
  scene.lights = {spot, lamp, sun};
  auto packed = packScene(scene);
  ASSERT_TRUE(packed.ok()) << packed.message();
  ASSERT_EQ(packed->lights.size(), 3u);
  EXPECT_EQ(packed->lightCounts, glm::uvec3(1, 1, 1)) << "sorted: directional, point, spot";
  for (const DrawItem& d : packed->opaque) {
    const std::vector<uint32_t> list(packed->lightLists.begin() + d.lightListOffset,
                                     packed->lightLists.begin() + d.lightListOffset + d.pointLightCount + d.spotLightCount);
    if (d.shapeIndex == 0) {
      EXPECT_EQ(d.pointLightCount, 1u);
      EXPECT_EQ(d.spotLightCount, 0u);
      EXPECT_EQ(list, std::vector<uint32_t>{1u});
    } else if (d.shapeIndex == 1) {
      EXPECT_EQ(d.pointLightCount, 0u);
      EXPECT_EQ(d.spotLightCount, 1u);
      EXPECT_EQ(list, std::vector<uint32_t>{2u});
    } else {
      EXPECT_EQ(d.pointLightCount + d.spotLightCount, 0u);
    }
  }
}

TEST(NormalMatrix, IsTheInverseTransposeUpToScale) {
  const glm::mat4 model = glm::rotate(glm::scale(glm::mat4(1.0f), glm::vec3(2.0f, 0.5f, 1.0f)), 0.7f, glm::vec3(1, 2, 3));
  const glm::mat3 expected = glm::transpose(glm::inverse(glm::mat3(model)));
  const glm::vec3 n = glm::normalize(glm::vec3(0.3f, -0.4f, 0.8f));
  const glm::vec3 a = glm::normalize(normalMatrix(model) * n);
  const glm::vec3 b = glm::normalize(expected * n);
  EXPECT_NEAR(glm::dot(a, b), 1.0f, 1e-5f);
}

TEST(NormalMatrix, KeepsNormalsOutwardUnderMirroring) {
  const glm::mat4 mirror = glm::scale(glm::mat4(1.0f), glm::vec3(-1, 1, 1));
  EXPECT_NEAR((normalMatrix(mirror) * glm::vec3(1, 0, 0)).x, -1.0f, 1e-6f);  // +X face moved to -X, faces -X
}

TEST(NormalMatrix, StaysFiniteForAFlattenedShape) {
  const glm::mat3 m = normalMatrix(glm::scale(glm::mat4(1.0f), glm::vec3(1, 0, 1)));
  const glm::vec3 n = m * glm::vec3(0, 1, 0);
  EXPECT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
  EXPECT_GT(n.y, 0.0f);
}

TEST(PackScene, SharedMeshIsStoredOnce) {
  Scene scene;
  auto mesh = triangle();
  scene.shapes.push_back(shapeOf(mesh));
  scene.shapes.push_back(shapeOf(mesh));
  scene.shapes.back().transform = glm::translate(glm::mat4(1.0f), glm::vec3(5, 0, 0));
  auto packed = packScene(scene);
  ASSERT_TRUE(packed.ok()) << packed.message();
  EXPECT_EQ(packed->vertices.size(), 3u);
  EXPECT_EQ(packed->indices.size(), 3u);
  ASSERT_EQ(packed->opaque.size(), 2u);
  EXPECT_EQ(packed->shapes.size(), 2u);
  EXPECT_EQ(packed->opaque[1].worldBounds.min.x, 5.0f);
}

TEST(PackScene, TransparencyDecidesTheDrawList) {
  Scene scene;
  Material glass;
  glass.transparency = 0.5f;
  scene.shapes.push_back(shapeOf(triangle(), glass));
  scene.shapes.push_back(shapeOf(triangle()));
  auto coloured = triangle();
  coloured->colors = {{1, 0, 0, 1}, {0, 1, 0, 0.5f}, {0, 0, 1, 1}};
  scene.shapes.push_back(shapeOf(coloured));
  auto packed = packScene(scene);
  ASSERT_TRUE(packed.ok());
  EXPECT_EQ(packed->opaque.size(), 1u);
  EXPECT_EQ(packed->transparent.size(), 2u);
  EXPECT_TRUE(packed->transparent[0].variant.blended);
}

TEST(PackScene, NoMaterialMeansUnlitAndLinesUseTheEmissiveColour) {
  Scene scene;
  scene.shapes.push_back(shapeOf(triangle(), std::nullopt));
  auto lines = std::make_shared<Mesh>();
  lines->topology = Topology::kLines;
  lines->positions = {{0, 0, 0}, {1, 0, 0}};
  lines->indices = {0, 1};
  Material m;
  m.emissiveColor = {1.0f, 0.5f, 0.0f};
  scene.shapes.push_back(shapeOf(lines, m));
  auto packed = packScene(scene);
  ASSERT_TRUE(packed.ok()) << packed.message();
  ASSERT_EQ(packed->shapes.size(), 2u);
  EXPECT_TRUE(packed->opaque[0].material.flags.x & kMaterialUnlit);
  EXPECT_EQ(glm::vec3(packed->opaque[0].material.diffuseAmbient), glm::vec3(1.0f));
  EXPECT_TRUE(packed->opaque[1].material.flags.x & kMaterialUnlit);
  EXPECT_NEAR(packed->opaque[1].material.diffuseAmbient.g, srgbToLinear(0.5f), 1e-6f);
  EXPECT_FALSE(packed->opaque[1].cullBackFaces);
}

TEST(PackScene, MirroredTransformFlipsTheFrontFace) {
  Scene scene;
  scene.shapes.push_back(shapeOf(triangle()));
  scene.shapes[0].transform = glm::scale(glm::mat4(1.0f), glm::vec3(1, 1, -1));
  auto packed = packScene(scene);
  ASSERT_TRUE(packed.ok());
  EXPECT_TRUE(packed->opaque[0].clockwiseFront);
}

TEST(PackScene, MissingNormalsAreGenerated) {
  Scene scene;
  auto mesh = triangle();
  mesh->normals.clear();
  scene.shapes.push_back(shapeOf(mesh));
  auto packed = packScene(scene);
  ASSERT_TRUE(packed.ok());
  EXPECT_NEAR(packed->vertices[0].normal.z, 1.0f, 1e-6f);
}

TEST(PackScene, BadIndexIsAnErrorNamingTheShape) {
  Scene scene;
  auto mesh = triangle();
  mesh->indices = {0, 1, 7};
  scene.shapes.push_back(shapeOf(mesh));
  scene.shapes[0].name = "wall";
  auto packed = packScene(scene);
  ASSERT_FALSE(packed.ok());
  EXPECT_EQ(packed.message(), "shape 'wall': index 7 (at 2) is out of range; the mesh has 3 vertices");
}

TEST(PackScene, MismatchedAttributesAndNonFiniteNumbersAreErrors) {
  Scene scene;
  auto mesh = triangle();
  mesh->texCoords = {{0, 0}};
  scene.shapes.push_back(shapeOf(mesh));
  auto packed = packScene(scene);
  ASSERT_FALSE(packed.ok());
  EXPECT_NE(packed.message().find("1 texture coordinates for 3 positions"), std::string::npos) << packed.message();

  Scene nanScene;
  nanScene.shapes.push_back(shapeOf(triangle()));
  nanScene.shapes[0].transform[3][0] = std::nanf("");
  EXPECT_FALSE(packScene(nanScene).ok());
}

TEST(PackScene, TextureWithoutImageNamesItsUrl) {
  Scene scene;
  scene.shapes.push_back(shapeOf(triangle()));
  auto texture = std::make_shared<Texture>();
  texture->url = "floor.jpg";
  auto appearance = std::make_shared<Appearance>(*scene.shapes[0].appearance);
  appearance->texture = texture;
  scene.shapes[0].appearance = appearance;
  auto packed = packScene(scene);
  ASSERT_FALSE(packed.ok());
  EXPECT_NE(packed.message().find("texture floor.jpg"), std::string::npos) << packed.message();
}

TEST(PackScene, SampleSceneHasEveryKindOfDraw) {
  auto packed = packScene(makeSampleScene());
  ASSERT_TRUE(packed.ok()) << packed.message();
  EXPECT_EQ(packed->opaque.size() + packed->transparent.size(), 13u);
  EXPECT_EQ(packed->transparent.size(), 1u);  // the glass pane
  EXPECT_EQ(packed->lights.size(), 2u);
  EXPECT_EQ(packed->textures.size(), 4u);
  bool lines = false, points = false, mirrored = false;
  for (const DrawItem& d : packed->opaque) {
    lines |= d.variant.topology == Topology::kLines;
    points |= d.variant.topology == Topology::kPoints;
    mirrored |= d.clockwiseFront;
  }
  EXPECT_TRUE(lines && points && mirrored);
  // Opaque draws come grouped by pipeline.
  for (size_t i = 1; i < packed->opaque.size(); ++i) {
    EXPECT_LE(packed->opaque[i - 1].variant.index(), packed->opaque[i].variant.index());
  }
}

}  // namespace
}  // namespace pw::engine::gpu
