// sRGB transfer functions (IEC 61966-2-1). The scene's colours are sRGB-encoded
// display values like its textures' texels; lighting adds light in linear space, and
// texture detail (texture_detail.h) and glTF's factors are in linear light too.
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

namespace pw::engine {

inline float srgbToLinear(float encoded) {
  const float c = std::clamp(std::isnan(encoded) ? 0.0f : encoded, 0.0f, 1.0f);
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

inline float linearToSrgb(float linear) {
  const float c = std::clamp(linear, 0.0f, 1.0f);
  return c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

inline glm::vec3 srgbToLinear(const glm::vec3& c) { return {srgbToLinear(c.r), srgbToLinear(c.g), srgbToLinear(c.b)}; }
inline glm::vec3 linearToSrgb(const glm::vec3& c) { return {linearToSrgb(c.r), linearToSrgb(c.g), linearToSrgb(c.b)}; }

}  // namespace pw::engine
