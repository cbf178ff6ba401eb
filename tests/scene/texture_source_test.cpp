// Texture::sourceFromTexCoord kept in WorldInfo-style info lines (texture_source.h).
#include <gtest/gtest.h>

#include "engine/scene/texture_source.h"

namespace pw::engine {
namespace {

std::shared_ptr<Texture> texture(const std::string& url) {
  auto t = std::make_shared<Texture>();
  t->image = std::make_shared<Image>();
  t->url = url;
  return t;
}

Shape shapeWith(std::shared_ptr<const Texture> t) {
  auto appearance = std::make_shared<Appearance>();
  appearance->texture = std::move(t);
  Shape shape;
  shape.mesh = std::make_shared<Mesh>();
  shape.appearance = std::move(appearance);
  return shape;
}

const glm::mat3 kSource(glm::vec3(3656.06f, -4.8e-5f, -1.5e-7f), glm::vec3(14887.56f, 8369.16f, 23.28f),
                        glm::vec3(-1459.3f, 2172.17f, 1.72f));

std::string urlOf(const Texture& t) { return t.url; }

TEST(TextureSource, LinesCarryTheHomographyBackToTheTexturesTheyName) {
  Scene scene;
  scene.info = {"a line of the user's own"};
  auto wall = texture("hall_left_wall.png");
  wall->sourceFromTexCoord = kSource;
  scene.shapes = {shapeWith(wall), shapeWith(wall), shapeWith(texture("other.png"))};
  const std::vector<std::string> info = infoWithTextureSources(scene, urlOf);
  ASSERT_EQ(info.size(), 2u) << "one line per texture, however many shapes use it";
  EXPECT_EQ(info[0], "a line of the user's own");
  EXPECT_EQ(info[1].rfind(kTextureSourceTag, 0), 0u);

  // As a reader sees it: the same textures without their source.
  Scene read;
  read.info = info;
  auto readWall = texture("hall_left_wall.png");
  auto other = texture("other.png");
  read.shapes = {shapeWith(readWall), shapeWith(readWall), shapeWith(other)};
  read.shapes.push_back(read.shapes[0]);  // the same appearance (DEF/USE)
  applyTextureSources(read);
  EXPECT_EQ(read.info, std::vector<std::string>{"a line of the user's own"});
  const Texture& first = *read.shapes[0].appearance->texture;
  ASSERT_TRUE(first.sourceFromTexCoord.has_value());
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) EXPECT_FLOAT_EQ((*first.sourceFromTexCoord)[c][r], kSource[c][r]);
  }
  EXPECT_EQ(read.shapes[0].appearance, read.shapes[3].appearance) << "shared appearances stay shared";
  EXPECT_EQ(read.shapes[0].appearance->texture, read.shapes[1].appearance->texture) << "and so do textures";
  EXPECT_FALSE(read.shapes[2].appearance->texture->sourceFromTexCoord.has_value());
  EXPECT_EQ(read.shapes[2].appearance->texture, other) << "untouched textures are not copied";

  // Writing what was read gives the same lines again, not a second copy of them.
  EXPECT_EQ(infoWithTextureSources(read, urlOf), info);
}

TEST(TextureSource, UrlsWithSpacesAndMalformedLinesAreHandled) {
  Scene scene;
  const std::string tag = kTextureSourceTag;
  scene.info = {tag + " 1 0 0 0 1 0 0 0 1 my wall.png", tag + " 1 2 3 wall.png", tag + " 1 0 0 0 1 0 0 0 nan x.png",
                tag + " 1 0 0 0 1 0 0 0 1"};
  auto spaced = texture("my wall.png");
  auto wall = texture("wall.png");
  scene.shapes = {shapeWith(spaced), shapeWith(wall)};
  applyTextureSources(scene);
  EXPECT_TRUE(scene.info.empty()) << "malformed texture-source lines are dropped, not kept as text";
  EXPECT_TRUE(scene.shapes[0].appearance->texture->sourceFromTexCoord.has_value());
  EXPECT_FALSE(scene.shapes[1].appearance->texture->sourceFromTexCoord.has_value());
}

TEST(TextureSource, FlippingTTwiceIsTheIdentity) {
  const glm::mat3 twice = withFlippedT(withFlippedT(kSource));
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) EXPECT_NEAR(twice[c][r], kSource[c][r], 1e-3f);
  }
  // (s, v) = (0.25, 0.75) is (s, t) = (0.25, 0.25).
  const glm::vec3 a = withFlippedT(kSource) * glm::vec3(0.25f, 0.75f, 1.0f);
  const glm::vec3 b = kSource * glm::vec3(0.25f, 0.25f, 1.0f);
  EXPECT_NEAR(a.x / a.z, b.x / b.z, 1e-2f);
  EXPECT_NEAR(a.y / a.z, b.y / b.z, 1e-2f);
}

}  // namespace
}  // namespace pw::engine
