#include "engine/gltf/png_encoder.h"

#include <filesystem>
#include <random>

#include <gtest/gtest.h>

namespace pw::engine::gltf {
namespace {

Image randomImage(int width, int height, bool withAlpha, uint32_t seed) {
  Image image = makeImage(width, height);
  std::mt19937 rng(seed);
  for (size_t i = 0; i < image.rgba.size(); ++i) {
    image.rgba[i] = (i % 4 == 3 && !withAlpha) ? 255 : static_cast<uint8_t>(rng());
  }
  return image;
}

Image decoded(const std::vector<uint8_t>& png) {
  auto image = decodeImage(png.data(), png.size(), "test.png");
  EXPECT_TRUE(image) << image.message();
  return image ? std::move(*image) : Image{};
}

uint8_t colourType(const std::vector<uint8_t>& png) { return png.at(25); }  // IHDR byte 9

TEST(PngEncoder, OpaqueImageRoundTripsAsRgb) {
  const Image image = randomImage(37, 23, false, 1);
  auto png = encodeTexturePng(image);
  ASSERT_TRUE(png) << png.message();
  EXPECT_EQ(colourType(*png), 2);
  EXPECT_EQ(decoded(*png), image);
}

TEST(PngEncoder, TranslucentImageRoundTripsAsRgba) {
  Image image = randomImage(16, 9, false, 2);
  image.pixel(15, 8)[3] = 254;  // one pixel is enough to need the alpha channel
  auto png = encodeTexturePng(image);
  ASSERT_TRUE(png) << png.message();
  EXPECT_EQ(colourType(*png), 6);
  EXPECT_EQ(decoded(*png), image);
}

TEST(PngEncoder, OnePixelAndOneRowImages) {
  for (const Image& image : {randomImage(1, 1, true, 3), randomImage(3001, 1, false, 4), randomImage(1, 700, true, 5)}) {
    auto png = encodeTexturePng(image);
    ASSERT_TRUE(png) << png.message();
    EXPECT_EQ(decoded(*png), image);
  }
}

TEST(PngEncoder, PhotoIsSmallerThanStbAndLossless) {
  const std::filesystem::path photo = std::filesystem::path(PW_SHARED_DIR) / "corridors" / "corridor_b.png";
  if (!std::filesystem::exists(photo)) GTEST_SKIP() << photo << " is not there";
  auto image = loadImage(photo);
  ASSERT_TRUE(image) << image.message();
  auto ours = encodeTexturePng(*image);
  auto stb = encodePng(*image);
  ASSERT_TRUE(ours && stb);
  EXPECT_EQ(decoded(*ours), *image);
  EXPECT_LT(ours->size(), stb->size());
}

TEST(PngEncoder, EmptyOrInconsistentImagesAreErrors) {
  EXPECT_FALSE(encodeTexturePng(Image{}));
  Image broken = makeImage(4, 4);
  broken.rgba.resize(10);
  EXPECT_FALSE(encodeTexturePng(broken));
}

}  // namespace
}  // namespace pw::engine::gltf
