// Every VRML97 file of tests/data/vrml-samples loads, with the shapes that file draws.
#include <gtest/gtest.h>

#include <map>

#include "engine/vrml/vrml_reader.h"
#include "engine/vrml/vrml_text.h"
#include "tests/vrml/vrml_samples.h"

namespace pw::engine {
namespace {

TEST(VrmlSamples, EveryVrml97SampleLoads) {
  const auto samples = vrmlSamples();
  ASSERT_FALSE(samples.empty()) << "no samples in " PW_TEST_DATA_DIR "/vrml-samples";
  // Shapes each file draws, counted by hand from the files (cones*: 20 and 4 Text).
  const std::map<std::string, size_t> expected = {
      {"proto_nested.wrl", 30},       {"proto_ultra_simple.wrl", 6}, {"deranged_house.wrl", 2},
      {"cones.wrl", 28},              {"cones.wrl.gz", 28},          {"cones_gzipped_but_with_normal_extension.wrl", 28},
      {"kings_head.wrl", 5},          {"texture_test.wrl", 6},       {"creaseangle.wrl", 3},
      {"cylinder_fields.wrl", 1},     {"group_2.wrl", 2},            {"group_2_lit.wrl", 2},
      {"inline.wrl", 10},             {"moving.wrl", 1},             {"navigation_viewpoint.wrl", 10},
      {"octree_example.wrl", 3},      {"pointset.wrl", 1},           {"reuse_cone.wrl", 2},
      {"reuse_coordinate.wrl", 3},    {"reuse_switch.wrl", 9},       {"reuse_texture.wrl", 2},
      {"reuse_texture_no.wrl", 2},    {"simplest_sphere_2.wrl", 1},  {"texture_transform_2.wrl", 5},
      {"transform.wrl", 2},           {"transform_accum_1.wrl", 3},  {"transform_accum_2.wrl", 3},
  };
  size_t loaded = 0;
  for (const auto& sample : samples) {
    SCOPED_TRACE(sample.string());
    Diagnostics d;
    auto scene = readVrml(sample, &d, samplesFolders());
    ASSERT_TRUE(scene.ok()) << scene.message();
    ++loaded;
    auto count = expected.find(sample.filename().string());
    ASSERT_NE(count, expected.end()) << "a sample this test does not know";
    // Without the DejaVu fonts (scripts/install-deps.sh installs them) Text is skipped.
    const bool textSkipped = sample.filename().string().starts_with("cones") && !vrml::fontFile("SERIF", "PLAIN");
    EXPECT_EQ(scene->shapes.size(), count->second - (textSkipped ? 4 : 0));
    for (const Shape& shape : scene->shapes) {
      EXPECT_TRUE(shape.mesh && !shape.mesh->indices.empty());
    }
  }
  EXPECT_EQ(loaded, expected.size());
}

TEST(VrmlSamples, TexturedSamplesFindTheirImagesThroughRelativeUrls) {
  const auto samples = vrmlSamples();
  if (samples.empty()) GTEST_SKIP() << "no samples";
  for (const auto& sample : samples) {
    const std::string name = sample.filename().string();
    if (name != "texture_test.wrl" && name != "deranged_house.wrl" && name != "kings_head.wrl") continue;
    Diagnostics d;
    auto scene = readVrml(sample, &d, samplesFolders());
    ASSERT_TRUE(scene.ok()) << scene.message();
    EXPECT_TRUE(scene->shapes[0].appearance && scene->shapes[0].appearance->texture) << name;
    EXPECT_EQ(d.format().find("no loadable image"), std::string::npos) << d.format();
  }
}

}  // namespace
}  // namespace pw::engine
