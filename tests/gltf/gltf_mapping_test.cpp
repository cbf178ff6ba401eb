#include "engine/gltf/gltf_mapping.h"
#include "engine/scene/camera.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace pw::engine::gltf {
namespace {

glm::mat4 compose(const Trs& trs) {
  return glm::translate(glm::mat4(1.0f), trs.translation) * glm::mat4_cast(trs.rotation) *
         glm::scale(glm::mat4(1.0f), trs.scale);
}

TEST(GltfMapping, RoughnessFollowsTheBlinnPhongExponent) {
  EXPECT_FLOAT_EQ(roughnessFromShininess(0.0f), 1.0f);
  EXPECT_NEAR(roughnessFromShininess(0.2f), std::pow(2.0 / 27.6, 0.25), 1e-6);
  EXPECT_NEAR(roughnessFromShininess(1.0f), std::pow(2.0 / 130.0, 0.25), 1e-6);
  EXPECT_GT(roughnessFromShininess(0.1f), roughnessFromShininess(0.9f));  // shinier is smoother
  EXPECT_FLOAT_EQ(roughnessFromShininess(7.0f), roughnessFromShininess(1.0f));  // clamped to VRML's range
}

TEST(GltfMapping, TrsRoundTripsRandomTransforms) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  for (int i = 0; i < 200; ++i) {
    Trs trs;
    trs.translation = glm::vec3(unit(rng), unit(rng), unit(rng)) * 50.0f;
    trs.rotation = glm::normalize(glm::quat(unit(rng), unit(rng), unit(rng), unit(rng)));
    trs.scale = glm::vec3(0.1f) + 3.0f * glm::abs(glm::vec3(unit(rng), unit(rng), unit(rng)));
    if (i % 3 == 0) trs.scale.y = -trs.scale.y;  // mirrors too
    const glm::mat4 m = compose(trs);
    const std::optional<Trs> back = decomposeTrs(m);
    ASSERT_TRUE(back) << "transform " << i;
    const glm::mat4 again = compose(*back);
    for (int c = 0; c < 4; ++c) {
      for (int r = 0; r < 4; ++r) EXPECT_NEAR(again[c][r], m[c][r], 2e-5f * 50.0f) << i << " " << c << r;
    }
    EXPECT_NEAR(glm::length(back->rotation), 1.0f, 1e-6f);
    EXPECT_EQ(glm::determinant(glm::mat3(again)) < 0, glm::determinant(glm::mat3(m)) < 0);
  }
}

TEST(GltfMapping, TrsRejectsShearProjectionZeroScaleAndNan) {
  glm::mat4 shear(1.0f);
  shear[1][0] = 0.5f;
  EXPECT_FALSE(decomposeTrs(shear));
  glm::mat4 projective(1.0f);
  projective[2][3] = -1.0f;
  EXPECT_FALSE(decomposeTrs(projective));
  EXPECT_FALSE(decomposeTrs(glm::scale(glm::mat4(1.0f), glm::vec3(1, 0, 1))));
  glm::mat4 nan(1.0f);
  nan[3][0] = std::nanf("");
  EXPECT_FALSE(decomposeTrs(nan));
  EXPECT_TRUE(decomposeTrs(glm::mat4(1.0f)));
}

TEST(GltfMapping, ColoursAreDecodedFromSrgb) {
  EXPECT_FLOAT_EQ(linearFromSrgb(0.0f), 0.0f);
  EXPECT_FLOAT_EQ(linearFromSrgb(1.0f), 1.0f);
  EXPECT_NEAR(linearFromSrgb(0.5f), 0.21404f, 1e-4f);
  EXPECT_NEAR(linearFromSrgb(0.04f), 0.04f / 12.92f, 1e-7f);  // the linear toe
  EXPECT_FLOAT_EQ(linearFromSrgb(std::nanf("")), 0.0f);
  EXPECT_FLOAT_EQ(linearFromSrgb(2.0f), 1.0f);
}

TEST(GltfMapping, ShortestDoubleKeepsTheFloat) {
  EXPECT_EQ(shortestDouble(0.8f), 0.8);
  EXPECT_EQ(static_cast<float>(shortestDouble(0.8f)), 0.8f);
  const float third = 1.0f / 3.0f;
  EXPECT_EQ(static_cast<float>(shortestDouble(third)), third);
  EXPECT_EQ(shortestDouble(std::numeric_limits<float>::infinity()), 0.0);
}

TEST(GltfMapping, InverseSquareLightsMapExactly) {
  Light bulb;
  bulb.intensity = 0.7f;
  bulb.attenuation = {0, 0, 2};
  // pi I / a2 at every distance where a2 d^2 >= 1.
  EXPECT_NEAR(punctualIntensity(bulb), glm::pi<float>() * 0.7f / 2.0f, 1e-5f);
}

TEST(GltfMapping, ConstantAttenuationIsMatchedAtTheReferenceDistance) {
  Light bulb;  // VRML default attenuation (1, 0, 0): no fall-off
  bulb.intensity = 1.0f;
  const float d = kLightMatchDistanceM;
  const float gltf = punctualIntensity(bulb);
  // glTF illuminance at d equals VRML's (times pi for glTF's Lambert 1/pi).
  EXPECT_NEAR(gltf / (d * d), glm::pi<float>() * 1.0f, 1e-5f);
  Light sun;
  sun.type = LightType::kDirectional;
  sun.intensity = 0.25f;
  EXPECT_NEAR(punctualIntensity(sun), glm::pi<float>() * 0.25f, 1e-6f);
}

TEST(GltfMapping, SpotConesAreOrderedAndInRange) {
  Light spot;
  spot.type = LightType::kSpot;
  spot.beamWidth = 0.3f;
  spot.cutOffAngle = 0.6f;
  SpotCone cone = spotCone(spot);
  EXPECT_FLOAT_EQ(cone.innerRad, 0.3f);
  EXPECT_FLOAT_EQ(cone.outerRad, 0.6f);
  spot.beamWidth = 1.57f;  // VRML default: wider than the cut-off, a hard edge
  spot.cutOffAngle = 0.785398f;
  cone = spotCone(spot);
  EXPECT_LT(cone.innerRad, cone.outerRad);
  EXPECT_GT(cone.innerRad, cone.outerRad - 0.01f);
  spot.cutOffAngle = 3.0f;
  EXPECT_FLOAT_EQ(spotCone(spot).outerRad, glm::half_pi<float>());
}

TEST(GltfMapping, CameraClipPlanesComeFromNavigationInfo) {
  Viewpoint viewpoint;
  viewpoint.fieldOfViewRad = 0.9f;
  NavigationInfo navigation;
  navigation.avatarRadiusM = 0.3f;
  PerspectiveCamera camera = perspectiveFromViewpoint(viewpoint, navigation);
  EXPECT_FLOAT_EQ(camera.yfovRad, 0.9f);
  EXPECT_FLOAT_EQ(camera.znearM, 0.15f);
  EXPECT_FLOAT_EQ(camera.zfarM, Camera{}.farM);  // infinite: the renderer's far plane
  navigation.visibilityLimitM = 50.0f;
  EXPECT_FLOAT_EQ(perspectiveFromViewpoint(viewpoint, navigation).zfarM, 50.0f);
  navigation.visibilityLimitM = 0.1f;  // nearer than the near plane would be
  camera = perspectiveFromViewpoint(viewpoint, navigation);
  EXPECT_FLOAT_EQ(camera.zfarM, 0.1f);
  EXPECT_LT(camera.znearM, camera.zfarM);
}

TEST(GltfMapping, DefaultTexCoordsFollowTheBoundingBox) {
  // 4 m along x, 2 m along y, 1 m along z: s along x, t along y up to 2 / 4.
  const std::vector<glm::vec3> positions = {{0, 0, 0}, {4, 0, 1}, {4, 2, 0}, {2, 1, 0.5f}};
  const std::vector<glm::vec2> st = defaultTexCoords(positions);
  ASSERT_EQ(st.size(), 4u);
  EXPECT_EQ(st[0], glm::vec2(0, 0));
  EXPECT_EQ(st[1], glm::vec2(1, 0));
  EXPECT_EQ(st[2], glm::vec2(1, 0.5f));
  EXPECT_EQ(st[3], glm::vec2(0.5f, 0.25f));
  // Ties prefer X, then Y: a cube maps s to x and t to y.
  const std::vector<glm::vec2> cube = defaultTexCoords({{0, 0, 0}, {1, 1, 1}});
  EXPECT_EQ(cube[1], glm::vec2(1, 1));
}

}  // namespace
}  // namespace pw::engine::gltf

namespace pw::engine::gltf {
namespace {

TEST(GltfMapping, ReadingInvertsWriting) {
  for (float x : {0.0f, 0.05f, 0.2f, 0.5f, 0.9f, 1.0f}) {
    EXPECT_NEAR(shininessFromRoughness(roughnessFromShininess(x)), x, 1e-4f) << x;
    EXPECT_NEAR(srgbFromLinear(linearFromSrgb(x)), x, 1e-5f) << x;
  }
  for (LightType type : {LightType::kDirectional, LightType::kPoint, LightType::kSpot}) {
    for (float candela : {0.5f, 3.0f, 12.0f}) {
      Light light;
      light.type = type;
      setIntensityFromPunctual(light, candela);
      // VRML intensity stops at 1: a directional light brighter than pi lux saturates.
      const float expected = type == LightType::kDirectional ? std::min(candela, glm::pi<float>()) : candela;
      EXPECT_NEAR(punctualIntensity(light), expected, 1e-4f * candela);
    }
  }
  Light faint;
  setIntensityFromPunctual(faint, 1e-40f);  // pi / I would overflow: the light is off
  EXPECT_EQ(faint.intensity, 0.0f);
  EXPECT_TRUE(std::isfinite(faint.attenuation.z));
}

TEST(GltfMapping, FlatteningTransforms) {
  EXPECT_FALSE(flattens(glm::mat4(1.0f)));
  EXPECT_FALSE(flattens(glm::scale(glm::mat4(1.0f), glm::vec3(1e-3f, 1e3f, 1.0f))));
  EXPECT_TRUE(flattens(glm::scale(glm::mat4(1.0f), glm::vec3(1, 0, 1))));
  EXPECT_TRUE(flattens(glm::mat4(0.0f)));
}

}  // namespace
}  // namespace pw::engine::gltf
