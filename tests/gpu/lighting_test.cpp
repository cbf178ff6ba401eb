// The renderer's shading against the VRML97 lighting equations (4.14.4), computed
// independently in vrml_lighting_reference.h: one quad facing the camera, the
// centre pixel (on the optical axis, so P = origin, V = +Z) compared within 2/255.
#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "engine/scene/color_space.h"
#include "tests/gpu/renderer_fixture.h"
#include "tests/gpu/vrml_lighting_reference.h"

namespace pw::engine {
namespace {

using engine::linearToSrgb;
using engine::srgbToLinear;

constexpr int kSize = 33;  // odd: the centre pixel's ray is the optical axis
constexpr float kFov = 0.8f;
constexpr float kEyeZ = 2.0f;

Camera frontCamera() {
  Camera camera;
  camera.position = {0, 0, kEyeZ};
  camera.fieldOfViewRad = kFov;
  return camera;
}

// A quad in z = 0 facing +Z, texture 0..1 over [-half, half]^2.
std::shared_ptr<Mesh> quadMesh(float half = 3.0f) {
  auto mesh = std::make_shared<Mesh>();
  mesh->positions = {{-half, -half, 0}, {half, -half, 0}, {half, half, 0}, {-half, half, 0}};
  mesh->normals.assign(4, glm::vec3(0, 0, 1));
  mesh->texCoords = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  mesh->indices = {0, 1, 2, 0, 2, 3};
  return mesh;
}

Scene quadScene(std::optional<Material> material, std::vector<Light> lights, std::shared_ptr<Mesh> mesh = quadMesh()) {
  Scene scene;
  scene.navigation.headlight = false;
  Shape shape;
  shape.mesh = std::move(mesh);
  auto appearance = std::make_shared<Appearance>();
  appearance->material = material;
  shape.appearance = appearance;
  scene.shapes.push_back(shape);
  scene.lights = std::move(lights);
  return scene;
}

Material testMaterial() {
  Material m;
  m.diffuseColor = {0.8f, 0.5f, 0.3f};
  m.ambientIntensity = 0.25f;
  m.emissiveColor = {0.05f, 0.0f, 0.1f};
  m.specularColor = {0.0f, 0.0f, 0.0f};
  m.shininess = 0.2f;
  return m;
}

// The reference surface at the centre pixel for a material (colours linearised as the renderer does).
test::ReferenceSurface centreSurface(const Material& m) {
  return {{0, 0, 0}, {0, 0, 1}, {0, 0, kEyeZ}, srgbToLinear(m.diffuseColor), m.ambientIntensity,
          srgbToLinear(m.emissiveColor), srgbToLinear(m.specularColor), m.shininess};
}

// Lights as the reference wants them: linear colours.
std::vector<Light> linearised(std::vector<Light> lights) {
  for (Light& l : lights) l.color = srgbToLinear(l.color);
  return lights;
}

class LightingTest : public test::RendererTest {
 protected:
  glm::ivec3 renderCentre(const Scene& scene, const FrameSettings& settings = {}) {
    auto set = renderer().setScene(scene);
    EXPECT_TRUE(set.ok()) << set.message();
    auto image = renderer().renderToImage(frontCamera(), kSize, kSize, settings);
    EXPECT_TRUE(image.ok()) << image.message();
    if (!image.ok()) return glm::ivec3(-1);
    const uint8_t* p = image->pixel(kSize / 2, kSize / 2);
    EXPECT_EQ(p[3], 255) << "frames are opaque";
    return {p[0], p[1], p[2]};
  }

  static glm::ivec3 encoded(const glm::vec3& linear) {
    const glm::vec3 s = linearToSrgb(linear) * 255.0f + 0.5f;
    return glm::ivec3(s);
  }

  static void expectNear(const glm::ivec3& actual, const glm::vec3& expectedLinear) {
    const glm::ivec3 expected = encoded(expectedLinear);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(actual[c], expected[c], 2) << "channel " << c << ": rendered (" << actual.r << ", " << actual.g
                                             << ", " << actual.b << "), VRML97 gives (" << expected.r << ", "
                                             << expected.g << ", " << expected.b << ")";
    }
  }
};

TEST_F(LightingTest, DirectionalLightGivesAmbientPlusDiffuse) {
  Light sun;
  sun.type = LightType::kDirectional;
  sun.direction = {0.0f, -0.6f, -0.8f};  // N . L = 0.8
  sun.color = {1.0f, 0.9f, 0.8f};
  sun.intensity = 0.7f;
  sun.ambientIntensity = 0.3f;
  const Material m = testMaterial();
  const glm::vec3 expected = test::vrmlLighting(centreSurface(m), linearised({sun}));
  expectNear(renderCentre(quadScene(m, {sun})), expected);
}

TEST_F(LightingTest, PointLightIsAttenuatedByDistance) {
  Light lamp;
  lamp.type = LightType::kPoint;
  lamp.position = {0.5f, 0.5f, 2.0f};  // d = 2.12: 1 / (1 + 0.3 d + 0.1 d^2) = 0.48
  lamp.attenuation = {1.0f, 0.3f, 0.1f};
  lamp.ambientIntensity = 0.2f;
  const Material m = testMaterial();
  const glm::vec3 expected = test::vrmlLighting(centreSurface(m), linearised({lamp}));
  ASSERT_LT(expected.r, 0.5f) << "the attenuation must matter in this case";
  expectNear(renderCentre(quadScene(m, {lamp})), expected);
}

TEST_F(LightingTest, PointLightBeyondItsRadiusGivesOnlyEmissive) {
  Light lamp;
  lamp.position = {0.0f, 0.0f, 3.0f};
  lamp.radius = 2.5f;
  lamp.ambientIntensity = 1.0f;
  const Material m = testMaterial();
  expectNear(renderCentre(quadScene(m, {lamp})), srgbToLinear(m.emissiveColor));
}

// A spot light 1 m in front of the centre, its axis tilted by `tilt` from the line to it.
Light tiltedSpot(float tilt) {
  Light spot;
  spot.type = LightType::kSpot;
  spot.position = {0.0f, 0.0f, 1.0f};
  spot.direction = {std::sin(tilt), 0.0f, -std::cos(tilt)};
  spot.beamWidth = 0.2f;
  spot.cutOffAngle = 0.5f;
  spot.ambientIntensity = 0.1f;
  return spot;
}

TEST_F(LightingTest, SpotLightIsFullInsideBeamWidth) {
  const Material m = testMaterial();
  const Light spot = tiltedSpot(0.1f);
  expectNear(renderCentre(quadScene(m, {spot})), test::vrmlLighting(centreSurface(m), linearised({spot})));
}

TEST_F(LightingTest, SpotLightFallsOffLinearlyBetweenBeamWidthAndCutOff) {
  const Material m = testMaterial();
  const Light spot = tiltedSpot(0.35f);  // spot factor (0.35 - 0.5) / (0.2 - 0.5) = 0.5
  const Light full = tiltedSpot(0.0f);
  const glm::vec3 expected = test::vrmlLighting(centreSurface(m), linearised({spot}));
  const glm::vec3 fullLit = test::vrmlLighting(centreSurface(m), linearised({full}));
  const glm::vec3 emissive = srgbToLinear(m.emissiveColor);
  ASSERT_NEAR((expected - emissive).r, 0.5f * (fullLit - emissive).r, 1e-4f);
  expectNear(renderCentre(quadScene(m, {spot})), expected);
}

TEST_F(LightingTest, SpotLightIsDarkBeyondCutOff) {
  const Material m = testMaterial();
  expectNear(renderCentre(quadScene(m, {tiltedSpot(0.6f)})), srgbToLinear(m.emissiveColor));
}

TEST_F(LightingTest, SpecularFollowsShininessTimes128) {
  Light sun;
  sun.type = LightType::kDirectional;
  sun.direction = -glm::normalize(glm::vec3(0.3f, 0.0f, 1.0f));  // the half vector is 8.5 degrees off N
  Material m = testMaterial();
  m.diffuseColor = {0.2f, 0.2f, 0.2f};
  m.specularColor = {1.0f, 1.0f, 1.0f};
  m.shininess = 0.1f;  // exponent 12.8: N . H = 0.989 gives 0.87
  const glm::vec3 expected = test::vrmlLighting(centreSurface(m), linearised({sun}));
  ASSERT_GT(expected.g - srgbToLinear(0.2f) * 0.958f, 0.5f) << "the specular term must dominate this case";
  expectNear(renderCentre(quadScene(m, {sun})), expected);
}

TEST_F(LightingTest, HeadlightIsAWhiteDirectionalLightAlongTheView) {
  Material m = testMaterial();
  m.specularColor = {0.3f, 0.3f, 0.3f};
  Light headlight;
  headlight.type = LightType::kDirectional;
  headlight.direction = {0, 0, -1};  // the camera looks along -Z
  const glm::vec3 expected = test::vrmlLighting(centreSurface(m), linearised({headlight}));
  FrameSettings settings;
  settings.headlight = true;
  expectNear(renderCentre(quadScene(m, {}), settings), expected);
  // And the scene's NavigationInfo decides when the settings do not.
  Scene scene = quadScene(m, {});
  scene.navigation.headlight = true;
  expectNear(renderCentre(scene), expected);
}

TEST_F(LightingTest, LightsThatAreOffAreIgnored) {
  Light sun;
  sun.type = LightType::kDirectional;
  sun.on = false;
  const Material m = testMaterial();
  expectNear(renderCentre(quadScene(m, {sun})), srgbToLinear(m.emissiveColor));
}

TEST_F(LightingTest, ShapeWithoutMaterialIsUnlitWhite) {
  Light sun;  // ignored: no material means no lighting (VRML97 6.5)
  sun.type = LightType::kDirectional;
  sun.intensity = 0.1f;
  expectNear(renderCentre(quadScene(std::nullopt, {sun})), glm::vec3(1.0f));
}

TEST_F(LightingTest, VertexColoursReplaceTheDiffuseColour) {
  auto mesh = quadMesh();
  mesh->colors.assign(4, glm::vec4(0.2f, 0.9f, 0.4f, 1.0f));
  Light sun;
  sun.type = LightType::kDirectional;
  const Material m = testMaterial();
  test::ReferenceSurface surface = centreSurface(m);
  surface.diffuse = srgbToLinear(glm::vec3(0.2f, 0.9f, 0.4f));
  expectNear(renderCentre(quadScene(m, {sun}, mesh)), test::vrmlLighting(surface, linearised({sun})));
}

TEST_F(LightingTest, TransparentShapeBlendsOverTheBackgroundInLinearLight) {
  Material m;
  m.diffuseColor = {0.0f, 0.0f, 0.0f};
  m.emissiveColor = {1.0f, 0.5f, 0.0f};
  m.transparency = 0.6f;
  Scene scene = quadScene(m, {});
  scene.backgroundColor = {0.0f, 0.2f, 1.0f};
  const glm::vec3 expected = 0.4f * srgbToLinear(m.emissiveColor) + 0.6f * srgbToLinear(scene.backgroundColor);
  expectNear(renderCentre(scene), expected);
}

// A two-sided (solid FALSE) quad turned away from the camera, and a sun lighting its
// other side: seen from behind it must be lit as if its normal faced the camera.
struct BackFacingCase {
  std::shared_ptr<Mesh> mesh;
  Light sun;
};
BackFacingCase backFacingTwoSidedQuad() {
  BackFacingCase c{quadMesh(), {}};
  for (glm::vec3& n : c.mesh->normals) n = -n;  // facing away from the camera
  std::swap(c.mesh->indices[1], c.mesh->indices[2]);
  std::swap(c.mesh->indices[4], c.mesh->indices[5]);
  c.mesh->solid = false;
  c.sun.type = LightType::kDirectional;
  c.sun.direction = {0.0f, -0.6f, -0.8f};
  return c;
}

TEST_F(LightingTest, SolidFalseLightsTheBackFaceWithTheFlippedNormal) {
  const BackFacingCase c = backFacingTwoSidedQuad();
  const Material m = testMaterial();
  expectNear(renderCentre(quadScene(m, {c.sun}, c.mesh)), test::vrmlLighting(centreSurface(m), linearised({c.sun})));
}

TEST_F(LightingTest, SolidTrueCullsTheBackFace) {
  auto back = quadMesh();
  std::swap(back->indices[1], back->indices[2]);
  std::swap(back->indices[4], back->indices[5]);
  Scene scene = quadScene(testMaterial(), {}, back);
  scene.backgroundColor = {0.0f, 1.0f, 0.0f};
  expectNear(renderCentre(scene), glm::vec3(0.0f, 1.0f, 0.0f));
}

// VRML97 table 4.5: a grey (1-component) texture modulates the diffuse colour of a lit
// shape, and is the colour itself (grey) of an unlit one.
TEST_F(LightingTest, GreyTextureModulatesTheDiffuseColour) {
  auto image = std::make_shared<Image>(makeImage(2, 2, 0x808080ff));
  image->grey = true;
  auto texture = std::make_shared<Texture>();
  texture->image = image;
  Light sun;
  sun.type = LightType::kDirectional;
  sun.direction = {0.0f, -0.6f, -0.8f};
  sun.intensity = 0.9f;
  sun.ambientIntensity = 0.2f;
  Material m = testMaterial();
  Scene scene = quadScene(m, {sun});
  auto appearance = std::make_shared<Appearance>(*scene.shapes[0].appearance);
  appearance->texture = texture;
  scene.shapes[0].appearance = appearance;
  test::ReferenceSurface surface = centreSurface(m);
  surface.diffuse *= srgbToLinear(128.0f / 255.0f);
  expectNear(renderCentre(scene), test::vrmlLighting(surface, linearised({sun})));

  appearance->material.reset();  // unlit: the texture's grey
  expectNear(renderCentre(scene), glm::vec3(srgbToLinear(128.0f / 255.0f)));
}

// The texture's top row must appear at the top: VRML's t = 0 is the image's bottom.
TEST_F(LightingTest, TextureIsUprightAndUnlitAtFullIntensity) {
  // 4x4 texels in 2x2 blocks: top red | green, bottom blue | white.
  auto image = std::make_shared<Image>(makeImage(4, 4));
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) {
      const uint32_t rgba = y < 2 ? (x < 2 ? 0xff0000ffu : 0x00ff00ffu) : (x < 2 ? 0x0000ffffu : 0xffffffffu);
      uint8_t* p = image->pixel(x, y);
      p[0] = uint8_t(rgba >> 24), p[1] = uint8_t(rgba >> 16), p[2] = uint8_t(rgba >> 8), p[3] = uint8_t(rgba);
    }
  }
  auto texture = std::make_shared<Texture>();
  texture->image = image;
  texture->wrapS = texture->wrapT = TextureWrap::kClamp;
  Scene scene = quadScene(std::nullopt, {}, quadMesh(kEyeZ * std::tan(kFov / 2)));  // fills the frame exactly
  auto appearance = std::make_shared<Appearance>();
  appearance->texture = texture;
  scene.shapes[0].appearance = appearance;
  ASSERT_TRUE(renderer().setScene(scene).ok());
  auto frame = renderer().renderToImage(frontCamera(), kSize, kSize);
  ASSERT_TRUE(frame.ok()) << frame.message();
  const auto at = [&](int x, int y) {
    const uint8_t* p = frame->pixel(x, y);
    return glm::ivec3(p[0], p[1], p[2]);
  };
  EXPECT_EQ(at(8, 8), glm::ivec3(255, 0, 0)) << "top left";
  EXPECT_EQ(at(24, 8), glm::ivec3(0, 255, 0)) << "top right";
  EXPECT_EQ(at(8, 24), glm::ivec3(0, 0, 255)) << "bottom left";
  EXPECT_EQ(at(24, 24), glm::ivec3(255, 255, 255)) << "bottom right";
}

// The interactive profile on a CPU device lights per vertex (PW_SPEC_VERTEX_LIGHTING)
// with the same equations: exact where the light does not vary over a face (a
// directional light), and close on a finely divided surface under a point light.
class VertexLightingTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    RendererOptions options;
    options.forceCpu = true;
    options.profile = RenderProfile::kInteractive;
    options.validation = RendererOptions::Validation::kOn;
    auto created = Renderer::create(options);
    ASSERT_TRUE(created.ok()) << created.message();
    interactive() = std::move(*created);
  }
  static void TearDownTestSuite() { interactive().reset(); }
  static std::unique_ptr<Renderer>& interactive() {
    static std::unique_ptr<Renderer> renderer;
    return renderer;
  }
  static glm::ivec3 centre(const Scene& scene) {
    EXPECT_TRUE(interactive()->setScene(scene).ok());
    auto image = interactive()->renderToImage(frontCamera(), kSize, kSize);
    EXPECT_TRUE(image.ok()) << image.message();
    if (!image.ok()) return glm::ivec3(-1);
    const uint8_t* p = image->pixel(kSize / 2, kSize / 2);
    return {p[0], p[1], p[2]};
  }
  static void expectNear(const glm::ivec3& actual, const glm::vec3& expectedLinear, int tolerance) {
    const glm::vec3 s = linearToSrgb(expectedLinear) * 255.0f + 0.5f;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(actual[c], int(s[c]), tolerance) << "channel " << c;
  }
};

// A (2n x 2n)-cell grid over [-half, half]^2 in z = 0 facing +Z: a vertex at the centre.
std::shared_ptr<Mesh> gridMesh(int n, float half = 3.0f) {
  auto mesh = std::make_shared<Mesh>();
  const int side = 2 * n + 1;
  for (int j = 0; j < side; ++j) {
    for (int i = 0; i < side; ++i) {
      mesh->positions.push_back({-half + 2 * half * i / (side - 1), -half + 2 * half * j / (side - 1), 0.0f});
      mesh->normals.push_back({0, 0, 1});
    }
  }
  for (int j = 0; j + 1 < side; ++j) {
    for (int i = 0; i + 1 < side; ++i) {
      const uint32_t a = j * side + i, b = a + 1, c = a + side + 1, d = a + side;
      mesh->indices.insert(mesh->indices.end(), {a, b, c, a, c, d});
    }
  }
  return mesh;
}

TEST_F(VertexLightingTest, InteractiveProfileOnLavapipeLightsPerVertexWithoutMsaaOrAnisotropy) {
  EXPECT_TRUE(interactive()->perVertexLighting());
  EXPECT_EQ(interactive()->msaaSamples(), 1);
  EXPECT_FALSE(interactive()->anisotropicFiltering());
}

TEST_F(VertexLightingTest, DirectionalLightMatchesTheEquationsExactly) {
  Light sun;
  sun.type = LightType::kDirectional;
  sun.direction = {0.0f, -0.6f, -0.8f};
  sun.color = {1.0f, 0.9f, 0.8f};
  sun.intensity = 0.7f;
  sun.ambientIntensity = 0.3f;
  const Material m = testMaterial();
  expectNear(centre(quadScene(m, {sun})), test::vrmlLighting(centreSurface(m), linearised({sun})), 2);
  EXPECT_EQ(interactive()->validationMessageCount(), 0u);
}

TEST_F(VertexLightingTest, PointLightAndSpecularOnAFineGridAreClose) {
  Light lamp;
  lamp.type = LightType::kPoint;
  lamp.position = {0.5f, 0.5f, 2.0f};
  lamp.attenuation = {1.0f, 0.3f, 0.1f};
  lamp.ambientIntensity = 0.2f;
  Material m = testMaterial();
  m.specularColor = {0.6f, 0.6f, 0.6f};
  m.shininess = 0.1f;
  expectNear(centre(quadScene(m, {lamp}, gridMesh(16))), test::vrmlLighting(centreSurface(m), linearised({lamp})), 2);
  EXPECT_EQ(interactive()->validationMessageCount(), 0u);
}

TEST_F(VertexLightingTest, TwoSidedSurfaceSeenFromBehindIsLitOnThatSide) {
  const BackFacingCase c = backFacingTwoSidedQuad();
  const Material m = testMaterial();
  expectNear(centre(quadScene(m, {c.sun}, c.mesh)), test::vrmlLighting(centreSurface(m), linearised({c.sun})), 2);
  EXPECT_EQ(interactive()->validationMessageCount(), 0u);
}

// A large face under a point light: the renderer cuts it up for per-vertex lighting,
// so the lamp's pool of light is not lost between its corners.
TEST_F(VertexLightingTest, LargeFacesAreCutUpForPointLights) {
  Light lamp;
  lamp.type = LightType::kPoint;
  lamp.position = {0.0f, 0.0f, 1.0f};
  lamp.attenuation = {1.0f, 0.0f, 1.0f};  // sharply falling off: corners and centre differ
  const Material m = testMaterial();
  expectNear(centre(quadScene(m, {lamp})), test::vrmlLighting(centreSurface(m), linearised({lamp})), 3);
  EXPECT_EQ(interactive()->validationMessageCount(), 0u);
}

TEST(VertexLightingChoice, TheInteractiveProfileCanStillLightPerPixel) {
  RendererOptions options;
  options.forceCpu = true;
  options.profile = RenderProfile::kInteractive;
  options.perVertexLighting = false;
  auto renderer = Renderer::create(options);
  ASSERT_TRUE(renderer.ok()) << renderer.message();
  EXPECT_FALSE((*renderer)->perVertexLighting());
  EXPECT_EQ((*renderer)->msaaSamples(), 1) << "the rest of the profile stays";
}

}  // namespace
}  // namespace pw::engine
