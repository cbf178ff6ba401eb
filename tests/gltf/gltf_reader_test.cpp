#include "engine/gltf/gltf_reader.h"

#include <filesystem>
#include <random>

#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>

#include "base/atomic_file.h"
#include "engine/gltf/gltf_mapping.h"
#include "engine/gltf/gltf_writer.h"
#include "engine/scene/camera.h"
#include "tests/gltf/gltf_read.h"
#include "tests/gltf/sample_scenes.h"

namespace pw::engine {
namespace {

namespace fs = std::filesystem;

Result<Scene> roundTrip(const Scene& scene, GltfContainer container, std::vector<std::string>* warnings = nullptr) {
  auto bytes = encodeGltf(scene, container);
  if (!bytes) return bytes.error();
  return parseGltf(*bytes, {}, "roundtrip", warnings);
}

Result<Scene> parseText(const std::string& json, std::vector<std::string>* warnings = nullptr,
                        const fs::path& baseDir = {}) {
  return parseGltf(std::span<const uint8_t>(reinterpret_cast<const uint8_t*>(json.data()), json.size()), baseDir,
                   "test.gltf", warnings);
}

glm::vec3 worldPoint(const Shape& shape, size_t vertex) {
  return glm::vec3(shape.transform * glm::vec4(shape.mesh->positions[vertex], 1.0f));
}

// The written-then-read scene shows what the original showed.
void expectSameScene(const Scene& original, const Scene& read) {
  ASSERT_EQ(read.shapes.size(), original.shapes.size());
  for (size_t i = 0; i < original.shapes.size(); ++i) {
    const Shape& a = original.shapes[i];
    const Shape& b = read.shapes[i];
    SCOPED_TRACE("shape " + a.name);
    EXPECT_EQ(b.name, a.name);
    ASSERT_EQ(b.mesh->positions.size(), a.mesh->positions.size());
    EXPECT_EQ(b.mesh->topology, a.mesh->topology);
    EXPECT_EQ(b.mesh->solid, a.mesh->solid);
    for (size_t v = 0; v < a.mesh->positions.size(); v += 97) {
      EXPECT_NEAR(glm::length(worldPoint(b, v) - worldPoint(a, v)), 0.0f, 2e-5f) << "vertex " << v;
    }
    if (a.mesh->topology != Topology::kPoints) {
      EXPECT_EQ(b.mesh->indices, a.mesh->indices);
    }
    const bool textured = a.appearance && a.appearance->texture && a.mesh->topology == Topology::kTriangles;
    if (textured) {
      ASSERT_TRUE(b.appearance && b.appearance->texture);
      EXPECT_EQ(b.appearance->texture->image->rgba, a.appearance->texture->image->rgba);
      EXPECT_EQ(b.appearance->texture->wrapS, a.appearance->texture->wrapS);
      ASSERT_EQ(b.mesh->texCoords.size(), a.mesh->texCoords.size());
      for (size_t v = 0; v < a.mesh->texCoords.size(); v += 97) {
        EXPECT_NEAR(glm::length(b.mesh->texCoords[v] - a.mesh->texCoords[v]), 0.0f, 1e-6f);
      }
    }
    if (!a.mesh->colors.empty() && !textured) {
      ASSERT_EQ(b.mesh->colors.size(), a.mesh->colors.size());
      for (size_t v = 0; v < a.mesh->colors.size(); ++v) {
        EXPECT_NEAR(glm::length(b.mesh->colors[v] - a.mesh->colors[v]), 0.0f, 1e-5f);
      }
    }
    const bool lit = a.appearance && a.appearance->material && a.mesh->topology == Topology::kTriangles;
    ASSERT_TRUE(b.appearance);
    EXPECT_EQ(b.appearance->material.has_value(), lit);
    if (lit) {
      const Material& m = *a.appearance->material;
      const Material& n = *b.appearance->material;
      if (!textured && a.mesh->colors.empty()) {
        EXPECT_NEAR(glm::length(n.diffuseColor - m.diffuseColor), 0.0f, 1e-5f);
      }
      EXPECT_NEAR(n.transparency, m.transparency, 1e-6f);
      EXPECT_NEAR(n.shininess, m.shininess, 1e-4f);
      EXPECT_NEAR(glm::length(n.emissiveColor - m.emissiveColor), 0.0f, 1e-5f);
    }
  }
  ASSERT_EQ(read.viewpoints.size(), original.viewpoints.size());
  for (size_t i = 0; i < original.viewpoints.size(); ++i) {
    const Viewpoint& a = original.viewpoints[i];
    const Viewpoint& b = read.viewpoints[i];
    EXPECT_EQ(b.description, a.description);
    EXPECT_NEAR(glm::length(b.position - a.position), 0.0f, 1e-5f);
    EXPECT_NEAR(b.fieldOfViewRad, a.fieldOfViewRad, 1e-6f);
    const glm::vec3 lookA = forwardOf(cameraFromViewpoint(a)), lookB = forwardOf(cameraFromViewpoint(b));
    EXPECT_NEAR(glm::length(lookB - lookA), 0.0f, 1e-5f);
    EXPECT_EQ(b.intrinsics, a.intrinsics);  // exactly, through asset.extras.info
  }
  EXPECT_EQ(read.tour, original.tour);
  size_t onLights = 0;
  for (const Light& light : original.lights) onLights += light.on ? 1 : 0;
  ASSERT_EQ(read.lights.size(), onLights);
  for (size_t i = 0, j = 0; i < original.lights.size(); ++i) {
    const Light& a = original.lights[i];
    if (!a.on) continue;
    const Light& b = read.lights[j++];
    EXPECT_EQ(b.type, a.type);
    EXPECT_NEAR(glm::length(b.color - a.color), 0.0f, 1e-5f);
    EXPECT_NEAR(gltf::punctualIntensity(b), gltf::punctualIntensity(a), 1e-4f);
    if (a.type != LightType::kDirectional) {
      EXPECT_NEAR(glm::length(b.position - a.position), 0.0f, 1e-5f);
    }
    if (a.type != LightType::kPoint) {
      EXPECT_NEAR(glm::dot(b.direction, glm::normalize(a.direction)), 1.0f, 1e-5f);
    }
  }
  EXPECT_EQ(read.title, original.title);
  EXPECT_EQ(read.info, original.info);
}

TEST(GltfReader, EverySampleRoundTripsThroughGlb) {
  for (const auto& sample : samples::allSamples()) {
    SCOPED_TRACE(sample.name);
    const Scene scene = sample.make();
    auto read = roundTrip(scene, GltfContainer::kGlb);
    ASSERT_TRUE(read) << read.message();
    expectSameScene(scene, *read);
  }
}

TEST(GltfReader, EmbeddedJsonRoundTrips) {
  const Scene scene = samples::everything();
  auto read = roundTrip(scene, GltfContainer::kEmbeddedJson);
  ASSERT_TRUE(read) << read.message();
  expectSameScene(scene, *read);
}

TEST(GltfReader, SharedMeshesAndAppearancesStayShared) {
  auto read = roundTrip(samples::sharedMesh(), GltfContainer::kGlb);
  ASSERT_TRUE(read) << read.message();
  const auto& shapes = read->shapes;
  ASSERT_EQ(shapes.size(), 4u);
  EXPECT_EQ(shapes[0].mesh, shapes[1].mesh);  // pillar_a, pillar_b
  EXPECT_EQ(shapes[0].appearance, shapes[1].appearance);
  EXPECT_NE(shapes[0].mesh, shapes[3].mesh);  // the sheared one was baked
}

TEST(GltfReader, ExternalBufferAndImageFilesResolveBesideTheFile) {
  const fs::path dir = testing::outputDir() / "external";
  fs::remove_all(dir);
  fs::create_directories(dir);
  // One triangle, float positions, in "my data.bin" (a space in the name: %20 in the URI).
  const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  ASSERT_TRUE(writeFileAtomic(dir / "my data.bin", std::span<const char>(reinterpret_cast<const char*>(positions), 36)));
  const std::string json = R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],
    "nodes":[{"mesh":0,"name":"tri"}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
    "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"}],
    "bufferViews":[{"buffer":0,"byteLength":36}],"buffers":[{"byteLength":36,"uri":"my%20data.bin"}]})";
  ASSERT_TRUE(writeFileAtomic(dir / "tri.gltf", json));
  auto read = readGltf(dir / "tri.gltf");
  ASSERT_TRUE(read) << read.message();
  ASSERT_EQ(read->shapes.size(), 1u);
  EXPECT_EQ(read->shapes[0].mesh->positions[1], glm::vec3(1, 0, 0));
  EXPECT_EQ(read->shapes[0].mesh->indices, (std::vector<uint32_t>{0, 1, 2}));  // non-indexed: 0..n-1
  EXPECT_TRUE(read->shapes[0].appearance->material);  // no material: glTF's default, lit white
  // The same document in memory, without a folder to resolve against: a clear error.
  auto refused = parseText(json);
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.message().find("my%20data.bin"), std::string::npos) << refused.message();
}

// A one-buffer document around `indices` (uint16) over four vertices of a unit square.
std::string squareDocument(int mode, const std::vector<uint16_t>& indices) {
  std::vector<uint8_t> bin;
  const float positions[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  bin.insert(bin.end(), reinterpret_cast<const uint8_t*>(positions), reinterpret_cast<const uint8_t*>(positions) + 48);
  bin.insert(bin.end(), reinterpret_cast<const uint8_t*>(indices.data()),
             reinterpret_cast<const uint8_t*>(indices.data()) + 2 * indices.size());
  static const char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string b64;
  for (size_t i = 0; i < bin.size(); i += 3) {
    const uint32_t v = bin[i] << 16 | (i + 1 < bin.size() ? bin[i + 1] << 8 : 0) | (i + 2 < bin.size() ? bin[i + 2] : 0);
    b64 += kAlphabet[v >> 18];
    b64 += kAlphabet[(v >> 12) & 63];
    b64 += i + 1 < bin.size() ? kAlphabet[(v >> 6) & 63] : '=';
    b64 += i + 2 < bin.size() ? kAlphabet[v & 63] : '=';
  }
  return R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
    "meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1,"mode":)" +
         std::to_string(mode) + R"(}]}],
    "accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3"},
                 {"bufferView":1,"componentType":5123,"count":)" +
         std::to_string(indices.size()) + R"(,"type":"SCALAR"}],
    "bufferViews":[{"buffer":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":)" +
         std::to_string(2 * indices.size()) + R"(}],
    "buffers":[{"byteLength":)" +
         std::to_string(bin.size()) + R"(,"uri":"data:application/octet-stream;base64,)" + b64 + R"("}]})";
}

TEST(GltfReader, StripsFansAndLoopsBecomeLists) {
  auto strip = parseText(squareDocument(5, {0, 1, 3, 2}));
  ASSERT_TRUE(strip) << strip.message();
  EXPECT_EQ(strip->shapes.at(0).mesh->indices, (std::vector<uint32_t>{0, 1, 3, 3, 1, 2}));  // both counter-clockwise
  auto fan = parseText(squareDocument(6, {0, 1, 2, 3}));
  ASSERT_TRUE(fan) << fan.message();
  EXPECT_EQ(fan->shapes.at(0).mesh->indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
  auto loop = parseText(squareDocument(2, {0, 1, 2, 3}));
  ASSERT_TRUE(loop) << loop.message();
  EXPECT_EQ(loop->shapes.at(0).mesh->topology, Topology::kLines);
  EXPECT_EQ(loop->shapes.at(0).mesh->indices, (std::vector<uint32_t>{0, 1, 1, 2, 2, 3, 3, 0}));
}

struct BadCase {
  const char* what;
  std::string document;
  const char* expected;  // a piece of the one-line error
};

TEST(GltfReader, MalformedFilesGiveOneLineErrors) {
  std::string oob = squareDocument(4, {0, 1, 2, 0, 2, 7});
  std::string outside = squareDocument(4, {0, 1, 2});
  outside.replace(outside.find("\"count\":4"), 9, "\"count\":5");
  std::string loop = squareDocument(4, {0, 1, 2});
  loop.replace(loop.find("\"nodes\":[{\"mesh\":0}]"), 20, "\"nodes\":[{\"mesh\":0,\"children\":[0]}]");
  std::string draco = squareDocument(4, {0, 1, 2});
  draco.replace(draco.find("{\"asset\""), 1, "{\"extensionsRequired\":[\"KHR_draco_mesh_compression\"],");
  std::string badBase64 = squareDocument(4, {0, 1, 2});
  badBase64.replace(badBase64.find("base64,") + 7, 1, "*");
  const std::vector<BadCase> cases = {
      {"not JSON", "{\"asset\": ", "not valid glTF JSON"},
      {"glTF 1", R"({"asset":{"version":"1.0"}})", "only 2.x"},
      {"no asset", R"({"nodes":[]})", "asset.version"},
      {"index out of range", oob, "index 5 is 7"},
      {"accessor past its view", outside, "do not fit"},
      {"node loop", loop, "node loop"},
      {"required extension", draco, "KHR_draco_mesh_compression"},
      {"bad base64", badBase64, "base64"},
  };
  for (const BadCase& c : cases) {
    auto read = parseText(c.document);
    ASSERT_FALSE(read) << c.what;
    EXPECT_NE(read.message().find(c.expected), std::string::npos) << c.what << ": " << read.message();
    EXPECT_EQ(read.message().find('\n'), std::string::npos) << c.what;
    EXPECT_EQ(read.message().rfind("test.gltf: ", 0), 0u) << c.what << ": " << read.message();
  }
}

TEST(GltfReader, TruncatedGlbIsAnError) {
  auto bytes = encodeGltf(samples::texturedQuad(), GltfContainer::kGlb);
  ASSERT_TRUE(bytes);
  bytes->resize(bytes->size() - 10);
  auto read = parseGltf(*bytes, {}, "cut.glb");
  ASSERT_FALSE(read);
  EXPECT_NE(read.message().find("truncated"), std::string::npos) << read.message();
}

TEST(GltfReader, MissingFileIsAnError) {
  auto read = readGltf(testing::outputDir() / "no_such_model.glb");
  ASSERT_FALSE(read);
  EXPECT_NE(read.message().find("no such file"), std::string::npos) << read.message();
}

// Damaged files (cut short, bytes changed) give a scene or an error, never a crash;
// whatever is read can be written again. A small in-test fuzzer (the libFuzzer target
// engine/gltf/fuzz/gltf_fuzz.cpp goes further).
TEST(GltfReader, DamagedFilesNeverCrash) {
  std::mt19937 rng(42);
  int readable = 0, rejected = 0;
  for (const auto& sample : {samples::texturedQuad(), samples::linesAndPoints(), samples::lights()}) {
    for (GltfContainer container : {GltfContainer::kGlb, GltfContainer::kEmbeddedJson}) {
      auto bytes = encodeGltf(sample, container);
      ASSERT_TRUE(bytes);
      for (int trial = 0; trial < 150; ++trial) {
        std::vector<uint8_t> damaged = *bytes;
        if (trial % 3 == 0) {
          damaged.resize(rng() % damaged.size());
        } else {
          for (int flips = 1 + trial % 4; flips > 0; --flips) damaged[rng() % damaged.size()] = static_cast<uint8_t>(rng());
        }
        auto read = parseGltf(damaged, {}, "damaged");
        if (!read) {
          ++rejected;
          continue;
        }
        ++readable;
        auto again = encodeGltf(*read, GltfContainer::kGlb);
        EXPECT_TRUE(again) << again.message();
      }
    }
  }
  EXPECT_GT(readable, 0);
  EXPECT_GT(rejected, 0);
}

TEST(GltfReader, WarnsAboutWhatItIgnores) {
  std::string doc = squareDocument(4, {0, 1, 2});
  doc.replace(doc.find("{\"asset\""), 1, "{\"animations\":[{\"channels\":[],\"samplers\":[]}],");
  std::vector<std::string> warnings;
  auto read = parseText(doc, &warnings);
  ASSERT_TRUE(read) << read.message();
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("animations"), std::string::npos) << warnings[0];
}

}  // namespace
}  // namespace pw::engine
