// A texture's detail layer (texture_detail.h): codes, composites, the base the
// renderer uploads, and the info line that carries the layer through files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "engine/scene/model_info.h"
#include "engine/scene/texture_detail.h"

namespace pw::engine {
namespace {

Image greyImage(int width, int height, uint8_t value) {
  Image image = makeImage(width, height, 0xffffffffu);
  for (size_t i = 0; i < image.rgba.size(); i += 4) image.rgba[i] = image.rgba[i + 1] = image.rgba[i + 2] = value;
  image.grey = true;
  return image;
}

TEST(TextureDetail, EveryCodeIsTheNearestCodeToItsOwnRatio) {
  for (int c = 0; c < 256; ++c) EXPECT_EQ(detailCode(detailRatio(static_cast<uint8_t>(c))), c);
  EXPECT_FLOAT_EQ(detailRatio(kNoDetail), 1.0f);
  EXPECT_FLOAT_EQ(detailRatio(kNoDetail + 64), 2.0f) << "64 codes an octave";
  EXPECT_EQ(detailCode(100.0f), 255) << "clamped to the codes there are";
  EXPECT_EQ(detailCode(0.0f), 0);
}

TEST(TextureDetail, TheBaseComesBackFromTheComposite) {
  std::mt19937 random(7);
  std::uniform_int_distribution<int> byte(0, 255), code(60, 200);
  int worst = 0;
  for (int n = 0; n < 20000; ++n) {
    const uint8_t base[3] = {static_cast<uint8_t>(byte(random)), static_cast<uint8_t>(byte(random)),
                             static_cast<uint8_t>(byte(random))};
    const uint8_t c = std::min(static_cast<uint8_t>(code(random)), detailCodeLimit(base));
    Texture texture;
    Image composite = makeImage(1, 1);
    applyDetail(base, c, composite.rgba.data());
    texture.image = std::make_shared<Image>(composite);
    texture.detail = std::make_shared<Image>(greyImage(1, 1, c));
    uint8_t staged[4];
    stageBaseAndDetail(texture, staged);
    ASSERT_EQ(staged[3], c) << "the code goes in alpha";
    // 8-bit composites lose some of a dark base's bits where the ratio darkens it.
    const int tolerance = c >= kNoDetail ? 1 : static_cast<int>(std::ceil(1.0f / detailRatio(c))) + 1;
    for (int k = 0; k < 3; ++k) {
      const int error = std::abs(staged[k] - base[k]);
      ASSERT_LE(error, tolerance) << "base " << int(base[k]) << " code " << int(c);
      worst = std::max(worst, c >= kNoDetail ? error : 0);
    }
  }
  EXPECT_LE(worst, 1);
}

TEST(TextureDetail, TheLimitKeepsTheBrightestChannelUnclipped) {
  for (int v = 1; v < 256; ++v) {
    const uint8_t base[3] = {static_cast<uint8_t>(v), static_cast<uint8_t>(v / 2), 0};
    const uint8_t limit = detailCodeLimit(base);
    ASSERT_GE(limit, kNoDetail);
    uint8_t composite[3];
    applyDetail(base, limit, composite);
    EXPECT_LE(linearOfSrgbByte(base[0]) * detailRatio(limit), 1.0f + 1e-6f) << v;
    if (limit < 255) {
      EXPECT_GT(linearOfSrgbByte(base[0]) * detailRatio(limit + 1), 1.0f) << "the largest such code, at " << v;
    }
  }
}

TEST(TextureDetail, WithoutALayerTheTextureIsItsOwnBase) {
  Texture texture;
  Image image = makeImage(2, 1, 0x204080ffu);
  texture.image = std::make_shared<Image>(image);
  texture.detail = std::make_shared<Image>(greyImage(3, 1, 200));  // the wrong size: not a layer
  EXPECT_FALSE(hasDetail(texture));
  uint8_t staged[8];
  stageBaseAndDetail(texture, staged);
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(staged[i * 4 + 0], image.rgba[i * 4 + 0]);
    EXPECT_EQ(staged[i * 4 + 2], image.rgba[i * 4 + 2]);
    EXPECT_EQ(staged[i * 4 + 3], kNoDetail);
  }
}

TEST(TextureDetail, TheLayersNameFollowsItsTextures) {
  EXPECT_EQ(detailUrl("hall_left_wall.png"), "hall_left_wall_detail.png");
  EXPECT_EQ(detailUrl("textures/hall floor.jpg"), "textures/hall floor_detail.png");
}

TEST(TextureDetail, AnInfoLineCarriesTheLayerThroughAFile) {
  auto wall = std::make_shared<Texture>();
  wall->image = std::make_shared<Image>(makeImage(4, 2));
  wall->url = "hall_left_wall.png";
  wall->sourceFromTexCoord = glm::mat3(2.0f);
  wall->detail = std::make_shared<Image>(greyImage(4, 2, 140));
  auto appearance = std::make_shared<Appearance>();
  appearance->texture = wall;
  Scene scene;
  scene.shapes.push_back({std::make_shared<Mesh>(), appearance, glm::mat4(1.0f), "wall"});
  const std::vector<std::string> info = infoForFile(scene, [](const Texture& t) { return t.url; });
  ASSERT_EQ(info.size(), 2u);
  EXPECT_EQ(info[1], std::string(kTextureDetailTag) + " hall_left_wall.png");

  // Read back: the reader's texture has no source and no layer until the lines say so.
  const auto readScene = [&](const ImageLoader& load) {
    Scene read;
    read.info = info;
    auto texture = std::make_shared<Texture>();
    texture->image = wall->image;
    texture->url = wall->url;
    auto a = std::make_shared<Appearance>();
    a->texture = texture;
    read.shapes.push_back({std::make_shared<Mesh>(), a, glm::mat4(1.0f), "wall"});
    takeModelInfo(read, load);
    EXPECT_TRUE(read.info.empty()) << "both lines are photowalk's";
    return read.shapes[0].appearance->texture;
  };
  std::string asked;
  const auto layer = readScene([&](const std::string& url) {
    asked = url;
    return std::make_shared<const Image>(greyImage(4, 2, 140));
  });
  EXPECT_EQ(asked, "hall_left_wall_detail.png");
  ASSERT_TRUE(layer->detail);
  EXPECT_EQ(layer->detail->rgba, wall->detail->rgba);
  EXPECT_FALSE(readScene({})->detail) << "no loader, no layer";
  EXPECT_FALSE(readScene([](const std::string&) { return std::make_shared<const Image>(greyImage(2, 2, 140)); })->detail)
      << "a layer of another size is dropped";
  EXPECT_FALSE(readScene([](const std::string&) { return nullptr; })->detail);
}

}  // namespace
}  // namespace pw::engine
