#include "engine/scene/image.h"

#include <stb_image_write.h>

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
  auto png = encodePng(image);
  ASSERT_TRUE(png) << png.message();
  EXPECT_EQ(colourType(*png), 2);
  EXPECT_EQ(decoded(*png), image);
}

TEST(PngEncoder, TranslucentImageRoundTripsAsRgba) {
  Image image = randomImage(16, 9, false, 2);
  image.pixel(15, 8)[3] = 254;  // one pixel is enough to need the alpha channel
  auto png = encodePng(image);
  ASSERT_TRUE(png) << png.message();
  EXPECT_EQ(colourType(*png), 6);
  EXPECT_EQ(decoded(*png), image);
}

TEST(PngEncoder, OnePixelAndOneRowImages) {
  for (const Image& image : {randomImage(1, 1, true, 3), randomImage(3001, 1, false, 4), randomImage(1, 700, true, 5)}) {
    auto png = encodePng(image);
    ASSERT_TRUE(png) << png.message();
    EXPECT_EQ(decoded(*png), image);
  }
}

TEST(PngEncoder, PhotoIsSmallerThanStbAndLossless) {
  const std::filesystem::path photo = std::filesystem::path(PW_GROUNDTRUTH_DIR) / "corridor_b.png";
  auto image = loadImage(photo);
  ASSERT_TRUE(image) << image.message();
  auto ours = encodePng(*image);
  std::vector<uint8_t> stbBytes;  // stb_image_write's encoder, compiled into pw_scene
  stbi_write_png_to_func(
      [](void* context, void* data, int size) {
        auto* bytes = static_cast<std::vector<uint8_t>*>(context);
        bytes->insert(bytes->end(), static_cast<uint8_t*>(data), static_cast<uint8_t*>(data) + size);
      },
      &stbBytes, image->width, image->height, 4, image->rgba.data(), image->width * 4);
  const std::vector<uint8_t>* stb = &stbBytes;
  ASSERT_TRUE(ours && !stb->empty());
  EXPECT_EQ(decoded(*ours), *image);
  EXPECT_LT(ours->size(), stb->size());
}

TEST(PngEncoder, EmptyOrInconsistentImagesAreErrors) {
  EXPECT_FALSE(encodePng(Image{}));
  Image broken = makeImage(4, 4);
  broken.rgba.resize(10);
  EXPECT_FALSE(encodePng(broken));
}

}  // namespace
}  // namespace pw::engine::gltf
