#include "engine/scene/image.h"

#include <algorithm>
#include <cstring>
#include <string>

#define STB_IMAGE_IMPLEMENTATION
#define STBI_FAILURE_USERMSG
#include <stb_image.h>
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>

#include "base/atomic_file.h"
#include "base/input_file.h"

namespace pw::engine {
namespace fs = std::filesystem;

Image makeImage(int width, int height, uint32_t fillRgba) {
  Image image;
  image.width = width;
  image.height = height;
  image.rgba.resize(static_cast<size_t>(width) * height * 4);
  const uint8_t px[4] = {uint8_t(fillRgba >> 24), uint8_t(fillRgba >> 16), uint8_t(fillRgba >> 8), uint8_t(fillRgba)};
  for (size_t i = 0; i < image.rgba.size(); i += 4) std::memcpy(&image.rgba[i], px, 4);
  return image;
}

Result<Image> decodeImage(const uint8_t* bytes, size_t size, const std::string& name) {
  if (size == 0) return makeError(name + ": the image file is empty");
  if (size > static_cast<size_t>(std::numeric_limits<int>::max())) return makeError(name + ": image file too large");
  int w = 0, h = 0, channels = 0;
  if (!stbi_info_from_memory(bytes, static_cast<int>(size), &w, &h, &channels)) {
    return makeError(name + ": not a readable image (" + stbi_failure_reason() + ")");
  }
  if (static_cast<int64_t>(w) * h > (int64_t{1} << 28)) {
    return makeError(name + ": image is " + std::to_string(w) + "x" + std::to_string(h) + ", larger than 268 megapixels");
  }
  stbi_uc* data = stbi_load_from_memory(bytes, static_cast<int>(size), &w, &h, &channels, 4);
  if (!data) return makeError(name + ": cannot decode image (" + stbi_failure_reason() + ")");
  Image image;
  image.width = w;
  image.height = h;
  image.rgba.assign(data, data + static_cast<size_t>(w) * h * 4);
  image.grey = channels <= 2;
  stbi_image_free(data);
  return image;
}

Result<Image> loadImage(const fs::path& path) {
  auto bytes = readInputFile(path, kTextureInput);
  if (!bytes) return bytes.error();
  return decodeImage(reinterpret_cast<const uint8_t*>(bytes->data()), bytes->size(), path.string());
}

namespace {
void appendBytes(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<uint8_t>*>(context);
  auto* p = static_cast<const uint8_t*>(data);
  out->insert(out->end(), p, p + size);
}
}  // namespace

Result<std::vector<uint8_t>> encodeJpeg(const Image& image, int quality) {
  if (image.empty()) return makeError("cannot encode an empty image");
  std::vector<uint8_t> bytes;
  if (!stbi_write_jpg_to_func(appendBytes, &bytes, image.width, image.height, 4, image.rgba.data(), std::clamp(quality, 1, 100))) {
    return makeError("JPEG encoding failed");
  }
  return bytes;
}

Result<std::vector<uint8_t>> encodeImage(const Image& image, const std::string& extension) {
  if (image.empty()) return makeError("cannot encode an empty image");
  std::string ext = extension;
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext != ".jpg" && ext != ".jpeg") return encodePng(image);
  return encodeJpeg(image, 92);
}

Status saveImage(const fs::path& path, const Image& image) {
  if (image.empty()) return makeError(path.string() + ": cannot save an empty image");
  auto bytes = encodeImage(image, path.extension().string());
  if (!bytes) return makeError(path.string() + ": " + bytes.message());
  return writeFileAtomic(path, std::span<const char>(reinterpret_cast<const char*>(bytes->data()), bytes->size()));
}

}  // namespace pw::engine
