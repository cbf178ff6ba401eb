#include "engine/gltf/gltf_mapping.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>

#include <glm/gtc/constants.hpp>

#include "engine/scene/camera.h"
#include "engine/scene/color_space.h"

namespace pw::engine::gltf {

int wrapCode(TextureWrap wrap) { return wrap == TextureWrap::kClamp ? kWrapClampToEdge : kWrapRepeat; }

float roughnessFromShininess(float shininess) {
  const double exponent = 128.0 * std::clamp(static_cast<double>(shininess), 0.0, 1.0);
  const double alphaSquared = 2.0 / (exponent + 2.0);
  return static_cast<float>(std::sqrt(std::sqrt(alphaSquared)));
}

std::optional<Trs> decomposeTrs(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      if (!std::isfinite(m[c][r])) return std::nullopt;
    }
  }
  // glm is column-major: m[c][r]. A TRS matrix has a last row of (0, 0, 0, 1).
  if (m[0][3] != 0.0f || m[1][3] != 0.0f || m[2][3] != 0.0f || m[3][3] != 1.0f) return std::nullopt;
  const glm::dmat3 linear(m);
  const double det = glm::determinant(linear);
  glm::dvec3 scale(glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2]));
  const double largest = std::max({scale.x, scale.y, scale.z});
  if (!(largest > 0.0) || std::abs(det) <= 1e-12 * largest * largest * largest) return std::nullopt;
  // A mirror is a negative scale on one axis; put it on x (the choice is arbitrary,
  // any axis gives the same matrix once the rotation absorbs the rest).
  if (det < 0) scale.x = -scale.x;
  const glm::dmat3 rotation(linear[0] / scale.x, linear[1] / scale.y, linear[2] / scale.z);
  // Shear leaves the columns non-orthogonal: R^T R is then not the identity.
  const glm::dmat3 gram = glm::transpose(rotation) * rotation;
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) {
      if (std::abs(gram[c][r] - (c == r ? 1.0 : 0.0)) > 1e-5) return std::nullopt;
    }
  }
  Trs trs;
  trs.translation = glm::vec3(m[3]);
  trs.rotation = glm::quat(glm::normalize(glm::quat_cast(rotation)));
  trs.scale = glm::vec3(scale);
  // Check the float result, which is what a reader will recompose.
  const glm::mat3 scaleMatrix(glm::vec3(trs.scale.x, 0, 0), glm::vec3(0, trs.scale.y, 0), glm::vec3(0, 0, trs.scale.z));
  const glm::mat3 back = glm::mat3_cast(trs.rotation) * scaleMatrix;
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) {
      if (std::abs(back[c][r] - m[c][r]) > 1e-5 * largest) return std::nullopt;
    }
  }
  return trs;
}

bool flattens(const glm::mat4& transform) {
  const glm::mat3 linear(transform);
  const float det = glm::determinant(linear);
  const float scale = std::max({glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2])});
  return !(std::abs(det) > 1e-12f * scale * scale * scale);
}

PerspectiveCamera perspectiveFromViewpoint(const Viewpoint& viewpoint, const NavigationInfo& navigation) {
  PerspectiveCamera camera;
  // VRML97 6.53: fieldOfView is the angle across the smaller side of the view; glTF's
  // yfov is always the vertical angle (glTF 2.0, 5.12). They agree for landscape
  // viewports, the shape of every walkthrough window; on a portrait viewport a glTF
  // viewer shows a wider view than a VRML browser. We leave aspectRatio out so that
  // the viewer keeps its own window's shape instead of stretching the picture.
  camera.yfovRad = viewpoint.fieldOfViewRad;
  // VRML97 6.29 recommends the near clipping plane at half the avatar's collision
  // radius (avatarSize[0]); without one, the renderer's own default.
  camera.znearM = navigation.avatarRadiusM > 0.0f ? 0.5f * navigation.avatarRadiusM : Camera{}.nearM;
  // visibilityLimit is the far clipping plane; 0 means infinite. glTF allows an
  // infinite projection (no zfar), but some loaders reject a camera without zfar
  // (Castle Game Engine's view3dscene 4.2: "missing zfar field"), so infinity becomes
  // the far plane photowalk's own renderer uses.
  camera.zfarM = Camera{}.farM;
  if (navigation.visibilityLimitM > 0.0f && std::isfinite(navigation.visibilityLimitM)) {
    camera.zfarM = navigation.visibilityLimitM;
  }
  if (camera.znearM >= camera.zfarM) camera.znearM = 1e-3f * camera.zfarM;
  return camera;
}

// VRML97 4.14.4 lights a surface with  albedo * I_vrml * att(d) * (N.L),  where
// att(d) = 1 / max(a0 + a1 d + a2 d^2, 1). glTF (2.0 Appendix B, KHR_lights_punctual)
// reflects  (albedo / pi) * E  with illuminance  E = I_gltf * (N.L) / d^2  for point
// and spot lights (I in candela) and  E = I_gltf * (N.L)  for directional ones (lux).
// Equal brightness therefore needs  I_gltf = pi * I_vrml * d^2 * att(d):  exactly
// pi * I_vrml for directional lights, and for point and spot lights exactly
// pi * I_vrml / a2 when only a2 is non-zero (inverse-square), for every d with
// a2 d^2 >= 1. Constant or linear VRML attenuation has no glTF form (glTF lights
// always fall off with 1/d^2), so we match it at kLightMatchDistanceM, about the
// distance from a ceiling light to the walls and floor of the corridors photowalk
// builds: nearer surfaces come out brighter than in VRML, farther ones darker.
float punctualIntensity(const Light& light) {
  const double intensity = std::max(0.0, static_cast<double>(light.intensity));
  if (light.type == LightType::kDirectional) return static_cast<float>(glm::pi<double>() * intensity);
  const double d = kLightMatchDistanceM;
  const glm::dvec3 a(light.attenuation);
  const double falloff = std::max(a.x + a.y * d + a.z * d * d, 1.0);
  return static_cast<float>(glm::pi<double>() * intensity * d * d / falloff);
}

void setIntensityFromPunctual(Light& light, float gltfIntensity) {
  const double intensity = std::isfinite(gltfIntensity) ? std::max(0.0, static_cast<double>(gltfIntensity)) : 0.0;
  if (light.type == LightType::kDirectional) {
    light.intensity = static_cast<float>(std::min(1.0, intensity / glm::pi<double>()));
    return;
  }
  // Below 1e-30 cd nothing is lit; and pi / I must stay a finite float.
  const bool lit = intensity > 1e-30;
  light.intensity = lit ? 1.0f : 0.0f;
  light.attenuation = glm::vec3(0.0f, 0.0f, lit ? static_cast<float>(glm::pi<double>() / intensity) : 1.0f);
}

float shininessFromRoughness(float roughness) {
  const double r = std::clamp(std::isnan(roughness) ? 1.0 : static_cast<double>(roughness), 1e-3, 1.0);
  const double exponent = 2.0 / (r * r * r * r) - 2.0;  // alpha^2 = r^4 = 2 / (n + 2)
  return static_cast<float>(std::clamp(exponent / 128.0, 0.0, 1.0));
}

// VRML97 6.45: full intensity inside beamWidth, falling linearly in angle to zero at
// cutOffAngle; beamWidth > cutOffAngle means a hard edge. KHR_lights_punctual falls
// off between innerConeAngle and outerConeAngle and needs inner < outer <= pi/2, so
// a hard edge becomes a 1 mrad falloff.
SpotCone spotCone(const Light& light) {
  constexpr float kHardEdgeRad = 1e-3f;
  SpotCone cone;
  cone.outerRad = std::clamp(light.cutOffAngle, 0.0f, glm::half_pi<float>());
  cone.innerRad = std::clamp(light.beamWidth, 0.0f, std::max(0.0f, cone.outerRad - kHardEdgeRad));
  return cone;
}


float linearFromSrgb(float encoded) { return srgbToLinear(encoded); }

glm::vec3 linearFromSrgb(const glm::vec3& encoded) { return srgbToLinear(encoded); }

float srgbFromLinear(float linear) {
  const float c = std::clamp(std::isnan(linear) ? 0.0f : linear, 0.0f, 1.0f);
  return c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

glm::vec3 srgbFromLinear(const glm::vec3& linear) {
  return {srgbFromLinear(linear.x), srgbFromLinear(linear.y), srgbFromLinear(linear.z)};
}

double shortestDouble(float value) {
  if (!std::isfinite(value)) return 0.0;
  char text[32];
  const auto [end, ec] = std::to_chars(text, text + sizeof(text) - 1, value);
  if (ec != std::errc()) return value;
  *end = '\0';
  return std::strtod(text, nullptr);
}

std::vector<glm::vec2> defaultTexCoords(const std::vector<glm::vec3>& positions) {
  Bounds bounds;
  for (const glm::vec3& p : positions) bounds.add(p);
  std::vector<glm::vec2> st(positions.size(), glm::vec2(0.0f));
  if (bounds.empty()) return st;
  const glm::vec3 size = bounds.size();
  // Stable sort by size, descending: equal sizes keep the X, Y, Z order.
  int axes[3] = {0, 1, 2};
  std::stable_sort(axes, axes + 3, [&](int a, int b) { return size[a] > size[b]; });
  const int sAxis = axes[0], tAxis = axes[1];
  const float longest = size[sAxis];
  if (!(longest > 0.0f)) return st;
  for (size_t i = 0; i < positions.size(); ++i) {
    st[i] = {(positions[i][sAxis] - bounds.min[sAxis]) / longest, (positions[i][tAxis] - bounds.min[tAxis]) / longest};
  }
  return st;
}

}  // namespace pw::engine::gltf
