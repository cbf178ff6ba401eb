#include "engine/scene/texture_detail.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>

#include "engine/scene/color_space.h"

namespace pw::engine {
namespace {

// Tables: a texel's three channels cost three lookups each way, not six pow() calls
// (a 12-megapixel photo's textures pass through here on every upload). The encoding
// table's steps (1/16384 of linear light) are finer than 8-bit sRGB's anywhere.
constexpr int kEncodeSteps = 16384;

struct Tables {
  std::array<float, 256> linear{};
  std::array<float, 256> ratio{};
  std::array<uint8_t, kEncodeSteps + 1> srgb{};
  Tables() {
    for (int i = 0; i < 256; ++i) {
      linear[i] = srgbToLinear(i / 255.0f);
      ratio[i] = std::exp2((i - kNoDetail) / kDetailCodesPerOctave);
    }
    for (int i = 0; i <= kEncodeSteps; ++i) {
      srgb[i] = static_cast<uint8_t>(std::lround(255.0f * linearToSrgb(static_cast<float>(i) / kEncodeSteps)));
    }
  }
  uint8_t encode(float linearValue) const {
    const float at = std::clamp(linearValue, 0.0f, 1.0f) * kEncodeSteps + 0.5f;
    return srgb[static_cast<size_t>(at)];
  }
};

const Tables& tables() {
  static const Tables t;
  return t;
}

}  // namespace

float detailRatio(uint8_t code) { return tables().ratio[code]; }

float linearOfSrgbByte(uint8_t encoded) { return tables().linear[encoded]; }

uint8_t detailCode(float ratio) {
  if (!(ratio > 0.0f)) return 0;
  const float code = kNoDetail + kDetailCodesPerOctave * std::log2(ratio);
  return static_cast<uint8_t>(std::clamp(std::lround(code), 0L, 255L));
}

uint8_t detailCodeLimit(const uint8_t* rgb) {
  const uint8_t brightest = std::max({rgb[0], rgb[1], rgb[2]});
  if (brightest == 0) return 255;
  // The largest code whose ratio keeps the brightest channel at or below 1.
  const float limit = kNoDetail + kDetailCodesPerOctave * std::log2(1.0f / tables().linear[brightest]);
  return static_cast<uint8_t>(std::clamp(static_cast<long>(std::floor(limit)), static_cast<long>(kNoDetail), 255L));
}

void applyDetail(const uint8_t* baseRgb, uint8_t code, uint8_t* compositeRgb) {
  const Tables& t = tables();
  if (code == kNoDetail) {
    std::memcpy(compositeRgb, baseRgb, 3);
    return;
  }
  const float r = t.ratio[code];
  for (int c = 0; c < 3; ++c) compositeRgb[c] = t.encode(t.linear[baseRgb[c]] * r);
}

bool hasDetail(const Texture& texture) {
  return texture.detail && texture.image && texture.detail->width == texture.image->width &&
         texture.detail->height == texture.image->height &&
         texture.detail->rgba.size() == texture.image->rgba.size();
}

void stageBaseAndDetail(const Texture& texture, uint8_t* out) {
  const Image& image = *texture.image;
  const size_t texels = static_cast<size_t>(image.width) * image.height;
  if (!hasDetail(texture)) {
    std::memcpy(out, image.rgba.data(), texels * 4);
    for (size_t i = 0; i < texels; ++i) out[i * 4 + 3] = kNoDetail;
    return;
  }
  const Tables& t = tables();
  const uint8_t* composite = image.rgba.data();
  const uint8_t* detail = texture.detail->rgba.data();
  for (size_t i = 0; i < texels; ++i) {
    const uint8_t code = detail[i * 4];
    uint8_t* o = out + i * 4;
    const uint8_t* c = composite + i * 4;
    if (code == kNoDetail) {
      std::memcpy(o, c, 3);
    } else {
      const float inverse = 1.0f / t.ratio[code];
      for (int k = 0; k < 3; ++k) o[k] = t.encode(t.linear[c[k]] * inverse);
    }
    o[3] = code;
  }
}

std::string detailUrl(const std::string& url) {
  const std::filesystem::path path(url);
  const std::string name = path.stem().string() + "_detail.png";
  return path.has_parent_path() ? (path.parent_path() / name).generic_string() : name;
}

}  // namespace pw::engine
