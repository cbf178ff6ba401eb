#include "engine/vrml/vrml_reader.h"

#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "engine/vrml/vrml_text.h"

namespace pw::engine {
namespace {

const std::string kData = PW_TEST_DATA_DIR "/vrml";

Result<Scene> readText(const std::string& body, Diagnostics* d = nullptr) {
  return readVrmlString("#VRML V2.0 utf8\n" + body, kData, d, "t.wrl");
}

Scene read(const std::string& body, Diagnostics* d = nullptr) {
  auto scene = readText(body, d);
  EXPECT_TRUE(scene.ok()) << scene.message();
  return scene.ok() ? std::move(*scene) : Scene{};
}

void expectNear(const glm::mat4& a, const glm::mat4& b) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(a[c][r], b[c][r], 1e-5f) << "column " << c << " row " << r;
  }
}

TEST(VrmlReader, TransformUsesEveryFieldInTheStandardOrder) {
  const Scene s = read(R"(Transform {
    translation 1 2 3  rotation 0 1 0 0.5  scale 2 3 4  scaleOrientation 1 0 0 0.3  center 0.5 -1 2
    children Transform { translation 0 0 -1 children Shape { geometry Box { } } } })");
  ASSERT_EQ(s.shapes.size(), 1u);
  // P' = T C R SR S -SR -C P (6.52), then the inner translation.
  const glm::vec3 c(0.5f, -1, 2);
  const glm::mat4 sr = glm::rotate(glm::mat4(1), 0.3f, glm::vec3(1, 0, 0));
  const glm::mat4 expected = glm::translate(glm::mat4(1), glm::vec3(1, 2, 3)) * glm::translate(glm::mat4(1), c) *
                             glm::rotate(glm::mat4(1), 0.5f, glm::vec3(0, 1, 0)) * sr *
                             glm::scale(glm::mat4(1), glm::vec3(2, 3, 4)) * glm::transpose(sr) *
                             glm::translate(glm::mat4(1), -c) * glm::translate(glm::mat4(1), glm::vec3(0, 0, -1));
  expectNear(s.shapes[0].transform, expected);
}

TEST(VrmlReader, SwitchShowsOnlyItsChoice) {
  EXPECT_EQ(read("Switch { choice [ Shape { geometry Box {} } ] }").shapes.size(), 0u);
  const Scene s = read(R"(Switch { whichChoice 1 choice [ Shape { geometry Box {} } DEF Two Shape { geometry Sphere {} } ] })");
  ASSERT_EQ(s.shapes.size(), 1u);
  EXPECT_EQ(s.shapes[0].name, "Two");
  EXPECT_EQ(read("Switch { whichChoice 5 choice [ Shape { geometry Box {} } ] }").shapes.size(), 0u);
}

TEST(VrmlReader, SharedNodesStayShared) {
  const Scene s = read(R"(
    Shape { appearance DEF A Appearance { material Material { } } geometry DEF G Box { } }
    Transform { translation 2 0 0 children Shape { appearance USE A geometry USE G } }
    Shape { appearance Appearance { texture DEF T ImageTexture { url "sub/checker.png" } } geometry Box { } }
    Shape { appearance Appearance { texture USE T } geometry Sphere { } }
    Shape { appearance Appearance { texture ImageTexture { url "sub/checker.png" } } geometry Sphere { } })");
  ASSERT_EQ(s.shapes.size(), 5u);
  EXPECT_EQ(s.shapes[0].mesh, s.shapes[1].mesh);
  EXPECT_EQ(s.shapes[0].appearance, s.shapes[1].appearance);
  EXPECT_EQ(s.shapes[2].appearance->texture, s.shapes[3].appearance->texture);
  // Another ImageTexture node of the same file: its own Texture, but one decoded image.
  EXPECT_NE(s.shapes[4].appearance->texture, s.shapes[3].appearance->texture);
  EXPECT_EQ(s.shapes[4].appearance->texture->image, s.shapes[3].appearance->texture->image);
}

TEST(VrmlReader, TexturesLoadRelativeToTheFileAndMissingOnesWarn) {
  Diagnostics d;
  auto scene = readVrml(kData + "/textured.wrl", &d);
  ASSERT_TRUE(scene.ok()) << scene.message();
  ASSERT_EQ(scene->shapes.size(), 2u);
  const auto& texture = scene->shapes[0].appearance->texture;
  ASSERT_TRUE(texture);
  EXPECT_EQ(texture->url, "sub/checker.png");
  EXPECT_EQ(texture->wrapS, TextureWrap::kClamp);
  EXPECT_EQ(texture->wrapT, TextureWrap::kRepeat);
  ASSERT_EQ(texture->image->width, 4);
  EXPECT_EQ(texture->image->pixel(3, 0)[2], 255);  // blue on the right
  EXPECT_EQ(texture->image->pixel(0, 1)[3], 128);  // half transparent bottom row
  EXPECT_EQ(scene->shapes[0].mesh->texCoords.size(), 4u);
  // The missing image: a warning, and the box is drawn untextured.
  EXPECT_FALSE(scene->shapes[1].appearance->texture);
  EXPECT_TRUE(scene->shapes[1].mesh->texCoords.empty());
  EXPECT_EQ(d.warningCount(), 1);
  EXPECT_NE(d.format().find("textured.wrl:15:37: ImageTexture has no loadable image"), std::string::npos);
}

TEST(VrmlReader, PixelTextureRowsStartAtTheBottom) {
  const Scene s = read("Shape { appearance Appearance { texture PixelTexture { image 1 2 3 0xFF0000 0x0000FF } } "
                       "geometry Box { } }");
  const Image& image = *s.shapes.at(0).appearance->texture->image;
  EXPECT_EQ(image.pixel(0, 0)[2], 255);  // top row: the second pixel listed (blue)
  EXPECT_EQ(image.pixel(0, 1)[0], 255);
}

TEST(VrmlReader, OneAndTwoComponentPixelTexturesAreGrey) {
  const Scene s = read("Shape { appearance Appearance { texture PixelTexture { image 1 1 1 0x80 } } geometry Box { } }\n"
                       "Shape { appearance Appearance { texture PixelTexture { image 1 1 2 0x80FF } } geometry Box { } }\n"
                       "Shape { appearance Appearance { texture PixelTexture { image 1 1 3 0x808080 } } geometry Box { } }");
  ASSERT_EQ(s.shapes.size(), 3u);
  EXPECT_TRUE(s.shapes[0].appearance->texture->image->grey);
  EXPECT_TRUE(s.shapes[1].appearance->texture->image->grey);
  EXPECT_FALSE(s.shapes[2].appearance->texture->image->grey);
}

// Text (6.47) with FontStyle (6.20): a quad per line in z = 0, textured with grey
// glyphs (alpha = coverage) that the Material colours; the first baseline at y = 0.
TEST(VrmlReader, TextIsAQuadPerLineTexturedWithItsGlyphs) {
  if (!vrml::fontFile("SERIF", "PLAIN")) GTEST_SKIP() << "no DejaVu fonts (fonts-dejavu-core)";
  const Scene s = read(R"(Shape {
    appearance Appearance { material Material { diffuseColor 1 0 0 } }
    geometry Text { string [ "Hello", "photowalk" ] fontStyle FontStyle { size 2 spacing 1.5 justify "MIDDLE" } }
  })");
  ASSERT_EQ(s.shapes.size(), 1u);
  const Shape& shape = s.shapes[0];
  ASSERT_EQ(shape.mesh->positions.size(), 8u);
  EXPECT_FALSE(shape.mesh->solid);
  ASSERT_TRUE(shape.appearance->material.has_value());
  EXPECT_EQ(shape.appearance->material->diffuseColor, glm::vec3(1, 0, 0));
  const Image& glyphs = *shape.appearance->texture->image;
  EXPECT_TRUE(glyphs.grey);
  int inked = 0;
  for (int y = 0; y < glyphs.height; ++y) {
    for (int x = 0; x < glyphs.width; ++x) inked += glyphs.pixel(x, y)[3] > 128;
  }
  EXPECT_GT(inked, 200) << "the glyphs are drawn";
  const auto& p = shape.mesh->positions;
  // MIDDLE: each line centred on x = 0; the second, longer line wider.
  EXPECT_NEAR(p[0].x, -p[1].x, 1e-4f);
  EXPECT_NEAR(p[4].x, -p[5].x, 1e-4f);
  EXPECT_GT(p[5].x - p[4].x, p[1].x - p[0].x);
  // Glyphs about `size` tall around the first baseline (y = 0): ascender above, descender below.
  EXPECT_GT(p[2].y, 1.5f);
  EXPECT_LT(p[0].y, 0.0f);
  EXPECT_GT(p[0].y, -1.0f);
  // The second line one size * spacing lower.
  EXPECT_NEAR(p[4].y - p[0].y, -3.0f, 1e-4f);
}

TEST(VrmlReader, ViewpointsNavigationLightsBackgroundWorldInfo) {
  const Scene s = read(R"(
    WorldInfo { title "Hall" info [ "one", "two" ] }
    WorldInfo { title "ignored: only the first counts" }
    NavigationInfo { headlight FALSE avatarSize [ 0.3 1.8 0.5 ] speed 2.5 type [ "EXAMINE" ] visibilityLimit 50 }
    Background { skyColor [ 0.1 0.2 0.3, 1 1 1 ] skyAngle [ 1 ] }
    Viewpoint { position 1 2 3 orientation 0 1 0 0.5 fieldOfView 1.2 description "Entrance" }
    Transform { translation 10 0 0 rotation 0 1 0 1.5707963267948966 children [
      Viewpoint { position 0 0 5 description "Side" }
      PointLight { location 0 0 1 attenuation 1 0.5 0 radius 7 color 1 0 0 }
      SpotLight { direction 0 0 -1 beamWidth 0.3 cutOffAngle 0.5 }
    ] }
    DirectionalLight { direction 0 -1 0 intensity 0.5 on FALSE })");
  EXPECT_EQ(s.title, "Hall");
  EXPECT_EQ(s.info, (std::vector<std::string>{"one", "two"}));
  EXPECT_FALSE(s.navigation.headlight);
  EXPECT_FLOAT_EQ(s.navigation.avatarHeightM, 1.8f);
  EXPECT_FLOAT_EQ(s.navigation.speedMps, 2.5f);
  EXPECT_EQ(s.navigation.type, (std::vector<std::string>{"EXAMINE"}));
  EXPECT_FLOAT_EQ(s.navigation.visibilityLimitM, 50.0f);
  EXPECT_EQ(s.backgroundColor, glm::vec3(0.1f, 0.2f, 0.3f));
  ASSERT_EQ(s.viewpoints.size(), 2u);
  EXPECT_EQ(s.viewpoints[0].description, "Entrance");
  EXPECT_EQ(s.viewpoints[0].orientation, glm::vec4(0, 1, 0, 0.5f));
  EXPECT_FLOAT_EQ(s.viewpoints[0].fieldOfViewRad, 1.2f);
  // Under the transform: (0 0 5) turned 90 degrees about Y lands on +X, then moved by 10.
  EXPECT_NEAR(s.viewpoints[1].position.x, 15.0f, 1e-5f);
  EXPECT_NEAR(s.viewpoints[1].position.z, 0.0f, 1e-5f);
  EXPECT_NEAR(s.viewpoints[1].orientation.y, 1.0f, 1e-6f);
  EXPECT_NEAR(s.viewpoints[1].orientation.w, 1.5707963f, 1e-6f);
  ASSERT_EQ(s.lights.size(), 3u);
  EXPECT_EQ(s.lights[0].type, LightType::kPoint);
  EXPECT_NEAR(s.lights[0].position.x, 11.0f, 1e-5f);
  EXPECT_EQ(s.lights[0].attenuation, glm::vec3(1, 0.5f, 0));
  EXPECT_FLOAT_EQ(s.lights[0].radius, 7.0f);
  EXPECT_EQ(s.lights[0].color, glm::vec3(1, 0, 0));
  EXPECT_EQ(s.lights[1].type, LightType::kSpot);
  EXPECT_NEAR(s.lights[1].direction.x, -1.0f, 1e-6f);  // -Z turned about Y
  EXPECT_FLOAT_EQ(s.lights[1].beamWidth, 0.3f);
  EXPECT_EQ(s.lights[2].type, LightType::kDirectional);
  EXPECT_FALSE(s.lights[2].on);
  EXPECT_FLOAT_EQ(s.lights[2].intensity, 0.5f);
}

TEST(VrmlReader, DegenerateDirectionsAreReplacedWithAWarning) {
  Diagnostics d;
  const Scene s = read("Viewpoint { orientation 0 0 0 1 } DirectionalLight { direction 0 0 0 }", &d);
  EXPECT_EQ(s.viewpoints.at(0).orientation, glm::vec4(0, 0, 1, 0));
  EXPECT_EQ(s.lights.at(0).direction, glm::vec3(0, 0, -1));
  EXPECT_EQ(d.warningCount(), 2);
}

TEST(VrmlReader, ProtoInstancesExpandWithIsMappings) {
  const Scene s = read(R"(
    PROTO Pillar [ field SFColor color 1 1 0  field SFFloat height 2  field MFNode extra [] ] {
      Group { children [
        Shape { appearance Appearance { material Material { diffuseColor IS color } } geometry Cylinder { height IS height } }
        Group { children IS extra }
      ] }
    }
    Pillar { }
    Transform { translation 5 0 0 children Pillar { color 0 0 1 height 4 extra Shape { geometry Sphere { } } } })");
  ASSERT_EQ(s.shapes.size(), 3u);
  EXPECT_EQ(s.shapes[0].appearance->material->diffuseColor, glm::vec3(1, 1, 0));
  EXPECT_FLOAT_EQ(localBounds(*s.shapes[0].mesh).max.y, 1.0f);
  EXPECT_EQ(s.shapes[1].appearance->material->diffuseColor, glm::vec3(0, 0, 1));
  EXPECT_FLOAT_EQ(localBounds(*s.shapes[1].mesh).max.y, 2.0f);
  EXPECT_FLOAT_EQ(s.shapes[2].transform[3].x, 5.0f);
}

TEST(VrmlReader, ExternProtoResolvesFromALocalFileAndReportsTheRest) {
  Diagnostics d;
  auto scene = readVrml(kData + "/externproto.wrl", &d);
  ASSERT_TRUE(scene.ok()) << scene.message();
  ASSERT_EQ(scene->shapes.size(), 2u);
  EXPECT_EQ(scene->shapes[0].appearance->material->diffuseColor, glm::vec3(0, 1, 0));
  EXPECT_EQ(scene->shapes[0].name, "A");
  EXPECT_FLOAT_EQ(localBounds(*scene->shapes[1].mesh).max.x, 0.5f);
  EXPECT_EQ(scene->shapes[1].appearance->material->diffuseColor, glm::vec3(1, 0, 0));
  EXPECT_EQ(d.warningCount(), 1);
  EXPECT_NE(d.format().find("EXTERNPROTO Missing is not resolved"), std::string::npos);
}

TEST(VrmlReader, InlineThatIncludesItselfStopsWithAWarning) {
  Diagnostics d;
  auto scene = readVrml(kData + "/inline_self.wrl", &d);
  ASSERT_TRUE(scene.ok()) << scene.message();
  EXPECT_EQ(scene->shapes.size(), 1u);
  EXPECT_NE(d.format().find("includes itself"), std::string::npos);
}

TEST(VrmlReader, FilesThatAreNotVrml97FailWithOneLine) {
  auto v1 = readVrml(kData + "/vrml1.wrl", nullptr);
  ASSERT_FALSE(v1.ok());
  EXPECT_NE(v1.message().find("VRML 1.0 is not supported"), std::string::npos);
  auto empty = readVrml(kData + "/empty.wrl", nullptr);
  ASSERT_FALSE(empty.ok());
  EXPECT_NE(empty.message().find("the file is empty"), std::string::npos);
  auto missing = readVrml(kData + "/no_such_file.wrl", nullptr);
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.message().find("no such file"), std::string::npos);
}

TEST(VrmlReader, DefUseMultiplicationIsRefused) {
  // Ten levels of ten USEs: 10^10 shapes. Refused quickly, not after filling memory.
  std::string text = "DEF L0 Shape { geometry Box { } }\n";
  for (int i = 1; i <= 10; ++i) {
    text += "DEF L" + std::to_string(i) + " Group { children [";
    for (int k = 0; k < 10; ++k) text += " USE L" + std::to_string(i - 1);
    text += " ] }\n";
  }
  auto scene = readText(text);
  ASSERT_FALSE(scene.ok());
  EXPECT_NE(scene.message().find("photowalk refuses it"), std::string::npos);
}

TEST(VrmlReader, ProtoMultiplicationIsRefused) {
  std::string text = "PROTO P0 [] { Shape { geometry Box { } } }\n";
  for (int i = 1; i <= 12; ++i) {
    text += "PROTO P" + std::to_string(i) + " [] { Group { children [";
    for (int k = 0; k < 10; ++k) text += " P" + std::to_string(i - 1) + " { }";
    text += " ] } }\n";
  }
  text += "P12 { }\n";
  auto scene = readText(text);
  ASSERT_FALSE(scene.ok());
  EXPECT_NE(scene.message().find("photowalk refuses it"), std::string::npos);
}

TEST(VrmlReader, NumbersThatMultiplyToInfinityAreAnError) {
  auto scene = readText("Transform { scale 1e30 1e30 1e30 children Transform { scale 1e30 1 1 children "
                        "Shape { geometry Box { } } } }");
  ASSERT_FALSE(scene.ok());
  EXPECT_NE(scene.message().find("too large"), std::string::npos);
}

}  // namespace
}  // namespace pw::engine
