// Read, write, read again: the same scene, bit for bit (tests/vrml/scene_compare.h).
#include <gtest/gtest.h>

#include <filesystem>

#include <glm/gtc/matrix_transform.hpp>

#include "engine/vrml/vrml_geometry.h"
#include "engine/vrml/vrml_reader.h"
#include "engine/vrml/vrml_writer.h"
#include "tests/vrml/scene_compare.h"
#include "tests/vrml/vrml_samples.h"

namespace pw::engine {
namespace {

namespace fs = std::filesystem;

fs::path outputDir() {
  const fs::path dir = fs::path(PW_BINARY_DIR) / "test_output" / "vrml" / "roundtrip";
  fs::create_directories(dir);
  return dir;
}

void expectRoundTrip(const Scene& original, const std::string& name) {
  const fs::path out = outputDir() / (name + ".wrl");
  const Status written = writeVrml(original, out);
  ASSERT_TRUE(written.ok()) << written.message();
  Diagnostics d;
  auto back = readVrml(out, &d);
  ASSERT_TRUE(back.ok()) << back.message();
  EXPECT_EQ(sceneDifference(original, *back), "") << out;
  EXPECT_EQ(d.warningCount(), 0) << d.format();
}

TEST(VrmlRoundTrip, EverySampleReadsBackExactly) {
  const auto samples = vrmlSamples();
  ASSERT_FALSE(samples.empty()) << "no samples in " PW_TEST_DATA_DIR "/vrml-samples";
  for (const fs::path& sample : samples) {
    SCOPED_TRACE(sample.string());
    auto scene = readVrml(sample, nullptr, samplesFolders());
    ASSERT_TRUE(scene.ok()) << scene.message();
    expectRoundTrip(*scene, sample.stem().string());
  }
}

TEST(VrmlRoundTrip, FixturesReadBackExactly) {
  for (const char* name : {"geometry_mix.wrl", "nonconvex.wrl", "externproto.wrl", "textured.wrl"}) {
    SCOPED_TRACE(name);
    auto scene = readVrml(fs::path(PW_TEST_DATA_DIR) / "vrml" / name, nullptr);
    ASSERT_TRUE(scene.ok()) << scene.message();
    expectRoundTrip(*scene, fs::path(name).stem().string());
  }
}

TEST(VrmlRoundTrip, AwkwardTransformsLightsAndFloats) {
  Scene s;
  auto mesh = std::make_shared<Mesh>(vrml::makeSphere(0.1f, false, 8, 4));
  const glm::mat4 transforms[] = {
      glm::rotate(glm::mat4(1), 1.5707963f, glm::vec3(0, 1, 0)),
      glm::rotate(glm::mat4(1), 3.14159265f, glm::vec3(1, 0, 0)),  // half turn
      glm::rotate(glm::mat4(1), 0.7f, glm::normalize(glm::vec3(1, 2, 3))) * glm::scale(glm::mat4(1), glm::vec3(1, 3, 0.5f)),
      glm::scale(glm::mat4(1), glm::vec3(-1, 1, 1)),  // mirror
      glm::translate(glm::mat4(1), glm::vec3(1e-7f, -123456.78f, 0.1f)) * glm::scale(glm::mat4(1), glm::vec3(1e-3f)),
      glm::rotate(glm::mat4(1), 0.3f, glm::vec3(0, 0, 1)) * glm::scale(glm::mat4(1), glm::vec3(2, 1, 1)) *
          glm::rotate(glm::mat4(1), -0.9f, glm::vec3(1, 1, 0)),  // a shear
  };
  for (const glm::mat4& t : transforms) {
    Shape shape;
    shape.mesh = mesh;
    shape.transform = t;
    s.shapes.push_back(shape);
  }
  Light spot;
  spot.type = LightType::kSpot;
  spot.position = {0.3f, 2.0f / 3.0f, -1e10f};
  spot.direction = {0.1f, -0.99f, 0.0f};
  spot.attenuation = {1, 0.01f, 0.001f};
  spot.on = false;
  s.lights.push_back(spot);
  s.lights.push_back(Light{});
  s.backgroundColor = {0.25f, 0.5f, 1.0f / 3.0f};
  s.navigation.type = {"WALK"};
  s.navigation.visibilityLimitM = 100;
  s.info = {"line \\ with \"quotes\"", ""};
  expectRoundTrip(s, "awkward");
}

// photowalk's own lines (model_info.h): a photo viewpoint's exact lens and the tour,
// typed in memory, come back exactly; a viewpoint without them stays without.
TEST(VrmlRoundTrip, PhotoIntrinsicsAndTourReadBackExactly) {
  Scene s;
  Viewpoint photo;
  photo.description = "Photo";
  photo.position = {0.5f, 1.65f, 6.0f};
  photo.orientation = {0.1f, -0.99f, 0.05f, 0.16f};
  photo.intrinsics = Intrinsics{760.0, 760.0, 541.5, 360.0, 1024, 768};
  Viewpoint overview;
  overview.description = "Overview";
  s.viewpoints = {photo, overview};
  s.tour = {{0, 1.65f, 5.5f}, {0, 1.65f, -15.0f}, {0.1f, 1.65f, 5.5f}};
  s.info = {"a line of the user's own"};
  expectRoundTrip(s, "photo_lines");
  const fs::path written = outputDir() / "photo_lines.wrl";
  auto back = readVrml(written, nullptr);
  ASSERT_TRUE(back.ok()) << back.message();
  EXPECT_EQ(back->info, s.info) << "photowalk's lines are taken out of the info";
  ASSERT_TRUE(back->viewpoints[0].intrinsics);
  EXPECT_EQ(back->viewpoints[0].intrinsics->principalU, 541.5);
  EXPECT_FALSE(back->viewpoints[1].intrinsics);
}

}  // namespace
}  // namespace pw::engine
