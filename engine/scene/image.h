// RGBA8 images and their PNG/JPEG files.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "base/result.h"

namespace pw::engine {

// 8-bit RGBA, rows top to bottom, no padding. Colour values are sRGB-encoded.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> rgba;  // width * height * 4 bytes
  // A grey image (1 or 2 components in its source: grey, grey + alpha; r = g = b). As a
  // texture it is an intensity map: it modulates the material's diffuse colour instead
  // of replacing it (VRML97 4.14.3, table 4.5). PNG files keep it grey (JPEG does not:
  // stb writes JPEGs in colour).
  bool grey = false;

  bool empty() const { return width <= 0 || height <= 0; }
  uint8_t* pixel(int x, int y) { return rgba.data() + (static_cast<size_t>(y) * width + x) * 4; }
  const uint8_t* pixel(int x, int y) const { return rgba.data() + (static_cast<size_t>(y) * width + x) * 4; }
  bool operator==(const Image&) const = default;
};

Image makeImage(int width, int height, uint32_t fillRgba = 0x000000ff);

// Loads PNG, JPEG (and the other formats stb_image reads) as RGBA8. The error names
// the file and says why it could not be read.
Result<Image> loadImage(const std::filesystem::path& path);
Result<Image> decodeImage(const uint8_t* bytes, size_t size, const std::string& nameForErrors);

// Writes PNG (or JPEG when the extension is .jpg/.jpeg, quality 92) atomically.
Status saveImage(const std::filesystem::path& path, const Image& image);
// Encodes as a file of this extension would hold it (JPEG for .jpg/.jpeg, else PNG).
Result<std::vector<uint8_t>> encodeImage(const Image& image, const std::string& extension);
// Encodes JPEG into memory, quality 1..100 (stb: baseline, 4:2:0 below 90).
Result<std::vector<uint8_t>> encodeJpeg(const Image& image, int quality);
// Encodes PNG into memory: Paeth-filtered rows, zlib (engine/scene/png_encoder.cpp).
Result<std::vector<uint8_t>> encodePng(const Image& image);

}  // namespace pw::engine
