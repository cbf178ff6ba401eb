#include "engine/gltf/gltf_writer.h"

#include <cmath>
#include <cstring>
#include <fstream>

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "base/atomic_file.h"
#include "engine/gltf/gltf_mapping.h"
#include "tests/gltf/gltf_read.h"
#include "tests/gltf/sample_scenes.h"

namespace pw::engine {
namespace {

namespace fs = std::filesystem;
using testing::outputDir;

// Writes `scene` as OUT/name.glb and reads it back with tinygltf.
tinygltf::Model writeAndRead(const Scene& scene, const std::string& name) {
  const fs::path path = outputDir() / (name + ".glb");
  const Status written = writeGltf(scene, path);
  EXPECT_TRUE(written) << written.message();
  auto model = testing::readGltfFile(path);
  EXPECT_TRUE(model) << model.message();
  return model ? std::move(*model) : tinygltf::Model{};
}

const tinygltf::Primitive& onlyPrimitive(const tinygltf::Model& model, int mesh) {
  return model.meshes.at(mesh).primitives.at(0);
}

int attribute(const tinygltf::Primitive& primitive, const std::string& name) {
  auto found = primitive.attributes.find(name);
  return found == primitive.attributes.end() ? -1 : found->second;
}

std::vector<double> factor(const tinygltf::Material& material) {
  return material.pbrMetallicRoughness.baseColorFactor;
}

glm::mat4 nodeMatrix(const tinygltf::Node& node) {
  glm::mat4 m(1.0f);
  if (!node.translation.empty()) {
    m = glm::translate(m, glm::vec3(node.translation[0], node.translation[1], node.translation[2]));
  }
  if (!node.rotation.empty()) {
    m *= glm::mat4_cast(glm::quat(float(node.rotation[3]), float(node.rotation[0]), float(node.rotation[1]),
                                  float(node.rotation[2])));
  }
  if (!node.scale.empty()) m = glm::scale(m, glm::vec3(node.scale[0], node.scale[1], node.scale[2]));
  return m;
}

const tinygltf::Node& nodeNamed(const tinygltf::Model& model, const std::string& name) {
  for (const tinygltf::Node& node : model.nodes) {
    if (node.name == name) return node;
  }
  ADD_FAILURE() << "no node named " << name;
  static const tinygltf::Node kNone;
  return kNone;
}

TEST(GltfWriter, TexturedQuadWithoutMaterialIsUnlitAndEmbedsItsTexture) {
  const tinygltf::Model model = writeAndRead(samples::texturedQuad(), "textured_quad");
  ASSERT_EQ(model.nodes.size(), 1u);
  ASSERT_EQ(model.materials.size(), 1u);
  const tinygltf::Material& material = model.materials[0];
  EXPECT_TRUE(material.extensions.count("KHR_materials_unlit"));
  EXPECT_NE(std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(), "KHR_materials_unlit"),
            model.extensionsUsed.end());
  EXPECT_TRUE(material.doubleSided);  // solid FALSE
  EXPECT_EQ(material.alphaMode, "OPAQUE");
  EXPECT_EQ(factor(material), (std::vector<double>{1, 1, 1, 1}));

  ASSERT_EQ(model.textures.size(), 1u);
  const tinygltf::Sampler& sampler = model.samplers.at(model.textures[0].sampler);
  EXPECT_EQ(sampler.wrapS, 33071);  // clamp
  EXPECT_EQ(sampler.wrapT, 10497);  // repeat
  EXPECT_EQ(sampler.minFilter, 9987);
  EXPECT_EQ(sampler.magFilter, 9729);
  const tinygltf::Image& image = model.images.at(model.textures[0].source);
  EXPECT_EQ(image.mimeType, "image/png");
  EXPECT_EQ(image.name, "far_wall.png");
  EXPECT_GE(image.bufferView, 0);
  const Image original = samples::gradientImage();
  ASSERT_EQ(image.width, original.width);
  ASSERT_EQ(image.height, original.height);
  EXPECT_EQ(image.image, original.rgba);  // lossless, pixel for pixel

  // The texel a glTF viewer shows at each corner is the one VRML shows there: VRML's
  // (s, t) = (0, 0) is the image's bottom-left, glTF's (u, v) = (0, 1).
  const tinygltf::Primitive& primitive = onlyPrimitive(model, 0);
  const std::vector<glm::vec2> uv = testing::readVec2(model, attribute(primitive, "TEXCOORD_0"));
  ASSERT_EQ(uv.size(), 4u);
  EXPECT_EQ(uv[0], glm::vec2(0, 1));
  EXPECT_EQ(uv[2], glm::vec2(1, 0));
  const int x = std::min(int(uv[0].x * image.width), image.width - 1);
  const int y = std::min(int(uv[0].y * image.height), image.height - 1);
  EXPECT_EQ(std::memcmp(&image.image[(y * image.width + x) * 4], original.pixel(0, 1), 4), 0);
}

TEST(GltfWriter, LitBoxApproximatesTheVrmlMaterial) {
  const tinygltf::Model model = writeAndRead(samples::litBox(), "lit_box");
  ASSERT_EQ(model.materials.size(), 1u);
  const tinygltf::Material& material = model.materials[0];
  EXPECT_FALSE(material.extensions.count("KHR_materials_unlit"));
  EXPECT_FALSE(material.doubleSided);
  const std::vector<double> base = factor(material);
  ASSERT_EQ(base.size(), 4u);
  EXPECT_NEAR(base[0], gltf::linearFromSrgb(0.8f), 1e-6);
  EXPECT_NEAR(base[1], gltf::linearFromSrgb(0.2f), 1e-6);
  EXPECT_NEAR(base[2], gltf::linearFromSrgb(0.1f), 1e-6);
  EXPECT_EQ(base[3], 1.0);
  EXPECT_EQ(material.pbrMetallicRoughness.metallicFactor, 0.0);
  EXPECT_NEAR(material.pbrMetallicRoughness.roughnessFactor, std::pow(2.0 / 66.0, 0.25), 1e-6);
  ASSERT_EQ(material.emissiveFactor.size(), 3u);
  EXPECT_NEAR(material.emissiveFactor[0], gltf::linearFromSrgb(0.1f), 1e-6);
  EXPECT_EQ(material.emissiveFactor[1], 0.0);

  const tinygltf::Node& node = nodeNamed(model, "box");
  EXPECT_EQ(node.translation, (std::vector<double>{0, 1, -2}));
  const tinygltf::Primitive& primitive = onlyPrimitive(model, node.mesh);
  EXPECT_EQ(primitive.mode, 4);
  const tinygltf::Accessor& position = model.accessors.at(attribute(primitive, "POSITION"));
  EXPECT_EQ(position.count, 24u);
  EXPECT_EQ(position.minValues, (std::vector<double>{-0.5, -1, -1.5}));
  EXPECT_EQ(position.maxValues, (std::vector<double>{0.5, 1, 1.5}));
  for (const glm::vec3& n : testing::readVec3(model, attribute(primitive, "NORMAL"))) {
    EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
  }
  const tinygltf::Accessor& indices = model.accessors.at(primitive.indices);
  EXPECT_EQ(indices.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
  EXPECT_EQ(testing::readIndices(model, primitive.indices), samples::litBox().shapes[0].mesh->indices);
  // A box is all faces, no lines or points: no TEXCOORD_0 without a texture.
  EXPECT_EQ(attribute(primitive, "TEXCOORD_0"), -1);
}

TEST(GltfWriter, TransparentMaterialBlends) {
  const tinygltf::Model model = writeAndRead(samples::transparentQuad(), "transparent_quad");
  ASSERT_EQ(model.materials.size(), 1u);
  EXPECT_EQ(model.materials[0].alphaMode, "BLEND");
  EXPECT_NEAR(factor(model.materials[0])[3], 0.6, 1e-6);
}

TEST(GltfWriter, SharedMeshIsWrittenOnceAndPlacedByEachNode) {
  const Scene scene = samples::sharedMesh();
  const tinygltf::Model model = writeAndRead(scene, "shared_mesh");
  ASSERT_EQ(model.nodes.size(), 4u);
  const tinygltf::Node& a = nodeNamed(model, "pillar_a");
  const tinygltf::Node& b = nodeNamed(model, "pillar_b");
  const tinygltf::Node& c = nodeNamed(model, "pillar_c");
  const tinygltf::Node& sheared = nodeNamed(model, "sheared");
  // Same mesh, equal appearances (two objects, same content): one glTF mesh.
  EXPECT_EQ(a.mesh, b.mesh);
  EXPECT_EQ(model.materials.size(), 2u);  // red and green
  // Another material needs another glTF mesh, but the vertex data stays shared.
  EXPECT_NE(a.mesh, c.mesh);
  EXPECT_EQ(attribute(onlyPrimitive(model, a.mesh), "POSITION"), attribute(onlyPrimitive(model, c.mesh), "POSITION"));
  EXPECT_EQ(onlyPrimitive(model, a.mesh).indices, onlyPrimitive(model, c.mesh).indices);

  const glm::mat4 placed = nodeMatrix(b);
  for (int col = 0; col < 4; ++col) {
    for (int row = 0; row < 4; ++row) EXPECT_NEAR(placed[col][row], scene.shapes[1].transform[col][row], 1e-5f);
  }

  // A shear has no TRS form: that shape's vertices are written transformed.
  EXPECT_TRUE(sheared.translation.empty() && sheared.rotation.empty() && sheared.scale.empty() &&
              sheared.matrix.empty());
  const int shearedPositions = attribute(onlyPrimitive(model, sheared.mesh), "POSITION");
  EXPECT_NE(shearedPositions, attribute(onlyPrimitive(model, a.mesh), "POSITION"));
  const std::vector<glm::vec3> baked = testing::readVec3(model, shearedPositions);
  const Mesh& mesh = *scene.shapes[3].mesh;
  ASSERT_EQ(baked.size(), mesh.positions.size());
  for (size_t i = 0; i < baked.size(); ++i) {
    const glm::vec3 expected(scene.shapes[3].transform * glm::vec4(mesh.positions[i], 1.0f));
    EXPECT_NEAR(glm::length(baked[i] - expected), 0.0f, 1e-6f);
  }
}

TEST(GltfWriter, MeshOver65535VerticesUsesUint32Indices) {
  const Scene scene = samples::bigMesh();
  const tinygltf::Model model = writeAndRead(scene, "big_mesh");
  const tinygltf::Primitive& primitive = onlyPrimitive(model, 0);
  const tinygltf::Accessor& indices = model.accessors.at(primitive.indices);
  EXPECT_EQ(indices.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
  EXPECT_EQ(indices.count, 300u * 300u * 6u);
  EXPECT_EQ(testing::readIndices(model, primitive.indices), scene.shapes[0].mesh->indices);
  EXPECT_EQ(testing::readVec3(model, attribute(primitive, "POSITION")), scene.shapes[0].mesh->positions);
}

TEST(GltfWriter, LinesAndPointsKeepTheirTopologyAndAreUnlit) {
  const tinygltf::Model model = writeAndRead(samples::linesAndPoints(), "lines_and_points");
  const tinygltf::Primitive& lines = onlyPrimitive(model, nodeNamed(model, "outline").mesh);
  const tinygltf::Primitive& points = onlyPrimitive(model, nodeNamed(model, "markers").mesh);
  EXPECT_EQ(lines.mode, 1);
  EXPECT_EQ(points.mode, 0);
  EXPECT_EQ(points.indices, -1);  // every vertex is a point
  const std::vector<glm::vec4> colors = testing::readVec4(model, attribute(lines, "COLOR_0"));
  ASSERT_EQ(colors.size(), 4u);
  EXPECT_EQ(colors[0], glm::vec4(1, 0, 0, 1));
  // VRML97 6.36: points with a Material are drawn in its emissive colour, unlit.
  const tinygltf::Material& glow = model.materials.at(points.material);
  EXPECT_TRUE(glow.extensions.count("KHR_materials_unlit"));
  EXPECT_NEAR(factor(glow)[1], gltf::linearFromSrgb(0.5f), 1e-6);
  EXPECT_EQ(factor(glow)[2], 0.0);
}

TEST(GltfWriter, ViewpointsBecomeNamedPerspectiveCameras) {
  const tinygltf::Model model = writeAndRead(samples::viewpoints(), "viewpoints");
  ASSERT_EQ(model.cameras.size(), 2u);
  EXPECT_EQ(model.cameras[0].type, "perspective");
  EXPECT_EQ(model.cameras[0].name, "Entrance");
  EXPECT_NEAR(model.cameras[0].perspective.yfov, 0.9, 1e-7);
  EXPECT_NEAR(model.cameras[0].perspective.znear, 0.15, 1e-7);
  EXPECT_NEAR(model.cameras[0].perspective.zfar, 80.0, 1e-7);
  EXPECT_EQ(model.cameras[0].perspective.aspectRatio, 0.0);  // the viewer's window decides
  const tinygltf::Node& side = nodeNamed(model, "Side");
  EXPECT_EQ(side.camera, 1);
  EXPECT_EQ(side.translation, (std::vector<double>{4, 1.6, -2}));  // the shortest form of 1.6f
  // The camera looks along its local -Z: rotated a quarter turn about +Y, along -X.
  const glm::vec3 forward = glm::mat3(nodeMatrix(side)) * glm::vec3(0, 0, -1);
  EXPECT_NEAR(forward.x, -1.0f, 1e-6f);
  EXPECT_NEAR(forward.z, 0.0f, 1e-6f);
}

TEST(GltfWriter, LightsUseKhrLightsPunctual) {
  const tinygltf::Model model = writeAndRead(samples::lights(), "lights");
  EXPECT_NE(std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(), "KHR_lights_punctual"),
            model.extensionsUsed.end());
  ASSERT_EQ(model.lights.size(), 3u);  // the switched-off one is left out
  EXPECT_EQ(model.lights[0].type, "directional");
  EXPECT_NEAR(model.lights[0].intensity, glm::pi<double>() * 0.5, 1e-5);
  EXPECT_EQ(model.lights[1].type, "point");
  EXPECT_NEAR(model.lights[1].intensity, glm::pi<double>(), 1e-5);  // inverse-square, a2 = 1
  EXPECT_NEAR(model.lights[1].range, 10.0, 1e-9);
  EXPECT_NEAR(model.lights[1].color[1], gltf::linearFromSrgb(0.9f), 1e-6);
  EXPECT_EQ(model.lights[2].type, "spot");
  EXPECT_NEAR(model.lights[2].spot.innerConeAngle, 0.3, 1e-7);
  EXPECT_NEAR(model.lights[2].spot.outerConeAngle, 0.6, 1e-7);

  const tinygltf::Node& spot = nodeNamed(model, "SpotLight 2");
  ASSERT_TRUE(spot.extensions.count("KHR_lights_punctual"));
  EXPECT_EQ(spot.extensions.at("KHR_lights_punctual").Get("light").Get<int>(), 2);
  EXPECT_EQ(spot.translation, (std::vector<double>{0, 2.5, -4}));
  const glm::vec3 shines = glm::mat3(nodeMatrix(spot)) * glm::vec3(0, 0, -1);
  EXPECT_NEAR(shines.y, -1.0f, 1e-6f);
}

TEST(GltfWriter, VertexColoursWithAlphaBlend) {
  const tinygltf::Model model = writeAndRead(samples::vertexColors(), "vertex_colors");
  const tinygltf::Primitive& primitive = onlyPrimitive(model, 0);
  const std::vector<glm::vec4> colors = testing::readVec4(model, attribute(primitive, "COLOR_0"));
  ASSERT_EQ(colors.size(), 4u);
  EXPECT_EQ(colors[3], glm::vec4(1, 1, 1, 0.5f));
  EXPECT_EQ(model.materials.at(primitive.material).alphaMode, "BLEND");
}

TEST(GltfWriter, GltfTextFileEmbedsTheSameData) {
  const Scene scene = samples::everything();
  const fs::path path = outputDir() / "everything.gltf";
  ASSERT_TRUE(writeGltf(scene, path));
  auto text = testing::readGltfFile(path);
  ASSERT_TRUE(text) << text.message();
  ASSERT_EQ(text->buffers.size(), 1u);
  EXPECT_EQ(text->buffers[0].uri.rfind("data:application/octet-stream;base64,", 0), 0u);
  const tinygltf::Model binary = writeAndRead(scene, "everything");
  EXPECT_EQ(text->buffers[0].data, binary.buffers[0].data);
  EXPECT_EQ(text->nodes.size(), binary.nodes.size());
  ASSERT_EQ(text->images.size(), 1u);
  EXPECT_EQ(text->images[0].image, samples::gradientImage().rgba);
  EXPECT_EQ(text->scenes.at(0).name, "photowalk sample scenes");
  EXPECT_EQ(text->asset.generator, "photowalk");
}

TEST(GltfWriter, GlbContainerIsWellFormed) {
  auto bytes = encodeGltf(samples::texturedQuad(), GltfContainer::kGlb);
  ASSERT_TRUE(bytes) << bytes.message();
  auto word = [&](size_t offset) {
    uint32_t v;
    std::memcpy(&v, bytes->data() + offset, 4);
    return v;
  };
  EXPECT_EQ(word(0), 0x46546C67u);
  EXPECT_EQ(word(4), 2u);
  EXPECT_EQ(word(8), bytes->size());
  const uint32_t jsonLength = word(12);
  EXPECT_EQ(jsonLength % 4, 0u);
  EXPECT_EQ(word(16), 0x4E4F534Au);
  const uint32_t binLength = word(20 + jsonLength);
  EXPECT_EQ(binLength % 4, 0u);
  EXPECT_EQ(word(24 + jsonLength), 0x004E4942u);
  EXPECT_EQ(28 + jsonLength + binLength, bytes->size());
}

TEST(GltfWriter, EmptySceneIsAValidFileWithoutBuffers) {
  const tinygltf::Model model = writeAndRead(Scene{}, "empty");
  EXPECT_TRUE(model.buffers.empty());
  ASSERT_EQ(model.scenes.size(), 1u);
  EXPECT_TRUE(model.scenes[0].nodes.empty());
}

TEST(GltfWriter, OneImageSharedByTexturesWithDifferentWrapping) {
  Scene scene = samples::texturedQuad();
  auto repeat = std::make_shared<Texture>(*scene.shapes[0].appearance->texture);
  repeat->wrapS = TextureWrap::kRepeat;
  auto appearance = std::make_shared<Appearance>();
  appearance->texture = repeat;
  Shape second = scene.shapes[0];
  second.appearance = appearance;
  second.name = "near_wall";
  scene.shapes.push_back(second);
  const tinygltf::Model model = writeAndRead(scene, "shared_image");
  EXPECT_EQ(model.images.size(), 1u);
  EXPECT_EQ(model.textures.size(), 2u);
  EXPECT_EQ(model.samplers.size(), 2u);
}

TEST(GltfWriter, MissingTexCoordsGetTheVrmlDefaultMapping) {
  Scene scene = samples::texturedQuad();
  Mesh mesh = *scene.shapes[0].mesh;
  mesh.texCoords.clear();
  scene.shapes[0].mesh = std::make_shared<Mesh>(mesh);
  const tinygltf::Model model = writeAndRead(scene, "default_texcoords");
  const std::vector<glm::vec2> uv = testing::readVec2(model, attribute(onlyPrimitive(model, 0), "TEXCOORD_0"));
  ASSERT_EQ(uv.size(), 4u);
  // The 2 x 1 quad: s along x over 0..1, t along y over 0..0.5, then v = 1 - t.
  EXPECT_EQ(uv[2], glm::vec2(1, 0.5f));
  EXPECT_EQ(uv[0], glm::vec2(0, 1));
}

TEST(GltfWriter, ZeroNormalsAreReplacedByUnitOnes) {
  Scene scene = samples::litBox();
  Mesh mesh = *scene.shapes[0].mesh;
  mesh.normals[0] = glm::vec3(0.0f);
  mesh.normals[1] *= 5.0f;
  scene.shapes[0].mesh = std::make_shared<Mesh>(mesh);
  const tinygltf::Model model = writeAndRead(scene, "zero_normals");
  const std::vector<glm::vec3> normals = testing::readVec3(model, attribute(onlyPrimitive(model, 0), "NORMAL"));
  for (const glm::vec3& n : normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
  EXPECT_NEAR(glm::dot(normals[1], mesh.normals[1] / 5.0f), 1.0f, 1e-6f);
}

TEST(GltfWriter, MissingFolderIsAnErrorAndWritesNothing) {
  const fs::path missing = outputDir() / "no_such_folder" / "scene.glb";
  const Status status = writeGltf(samples::litBox(), missing);
  ASSERT_FALSE(status);
  EXPECT_NE(status.message().find("does not exist"), std::string::npos) << status.message();
  EXPECT_EQ(status.message().find('\n'), std::string::npos);
  EXPECT_FALSE(fs::exists(missing.parent_path()));
}

TEST(GltfWriter, UnknownExtensionIsAnError) {
  const Status status = writeGltf(samples::litBox(), outputDir() / "scene.obj");
  ASSERT_FALSE(status);
  EXPECT_NE(status.message().find(".glb"), std::string::npos) << status.message();
  EXPECT_FALSE(fs::exists(outputDir() / "scene.obj"));
}

TEST(GltfWriter, BadSceneLeavesTheExistingFileUntouched) {
  const fs::path dir = outputDir() / "keep";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path path = dir / "keep.glb";
  ASSERT_TRUE(writeFileAtomic(path, std::string("old contents")));
  Scene scene = samples::litBox();
  Mesh mesh = *scene.shapes[0].mesh;
  mesh.positions[5].y = std::nanf("");
  scene.shapes[0].mesh = std::make_shared<Mesh>(mesh);
  const Status status = writeGltf(scene, path);
  ASSERT_FALSE(status);
  EXPECT_NE(status.message().find("shape 'box'"), std::string::npos) << status.message();
  EXPECT_NE(status.message().find("vertex 5"), std::string::npos) << status.message();
  EXPECT_EQ(*readFile(path), "old contents");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);  // no temporary left
}

TEST(GltfWriter, IndexOutOfRangeIsAnError) {
  Scene scene = samples::transparentQuad();
  Mesh mesh = *scene.shapes[0].mesh;
  mesh.indices[4] = 4;
  scene.shapes[0].mesh = std::make_shared<Mesh>(mesh);
  auto bytes = encodeGltf(scene, GltfContainer::kGlb);
  ASSERT_FALSE(bytes);
  EXPECT_NE(bytes.message().find("only 4 vertices"), std::string::npos) << bytes.message();
}

TEST(GltfWriter, PartialTriangleIsAnError) {
  Scene scene = samples::transparentQuad();
  Mesh mesh = *scene.shapes[0].mesh;
  mesh.indices.pop_back();
  scene.shapes[0].mesh = std::make_shared<Mesh>(mesh);
  EXPECT_FALSE(encodeGltf(scene, GltfContainer::kGlb));
}

TEST(GltfWriter, FieldOfViewOutsideZeroToPiIsAnError) {
  Scene scene = samples::viewpoints();
  scene.viewpoints[1].fieldOfViewRad = 3.5f;
  auto bytes = encodeGltf(scene, GltfContainer::kGlb);
  ASSERT_FALSE(bytes);
  EXPECT_NE(bytes.message().find("viewpoint 'Side'"), std::string::npos) << bytes.message();
}

TEST(GltfWriter, MirroredShapesShareAMirroredMeshUnderPositiveTransforms) {
  Scene scene = samples::litBox();
  const glm::mat4 mirror = glm::scale(glm::mat4(1.0f), glm::vec3(-1, 1, 1));
  scene.shapes.push_back(scene.shapes[0]);
  scene.shapes.back().transform = glm::translate(glm::mat4(1.0f), glm::vec3(3, 0, 0)) * mirror;
  scene.shapes.back().name = "mirrored_a";
  scene.shapes.push_back(scene.shapes[0]);
  scene.shapes.back().transform =
      glm::translate(glm::mat4(1.0f), glm::vec3(-3, 0, 0)) * glm::rotate(glm::mat4(1.0f), 0.5f, glm::vec3(0, 1, 0)) *
      glm::scale(glm::mat4(1.0f), glm::vec3(1, 1, -2));
  scene.shapes.back().name = "mirrored_b";
  const tinygltf::Model model = writeAndRead(scene, "mirrored");
  const tinygltf::Node& plain = nodeNamed(model, "box");
  const tinygltf::Node& a = nodeNamed(model, "mirrored_a");
  const tinygltf::Node& b = nodeNamed(model, "mirrored_b");
  EXPECT_EQ(a.mesh, b.mesh);      // one mirrored copy, shared
  EXPECT_NE(a.mesh, plain.mesh);  // and not the original
  const Mesh& original = *scene.shapes[0].mesh;
  for (size_t shapeIndex : {size_t{1}, size_t{2}}) {
    const tinygltf::Node& node = model.nodes.at(shapeIndex);
    const glm::mat4 placed = nodeMatrix(node);
    EXPECT_GT(glm::determinant(glm::mat3(placed)), 0.0f);  // viewers need not flip the winding
    const tinygltf::Primitive& primitive = onlyPrimitive(model, node.mesh);
    const std::vector<glm::vec3> positions = testing::readVec3(model, attribute(primitive, "POSITION"));
    const std::vector<uint32_t> indices = testing::readIndices(model, primitive.indices);
    ASSERT_EQ(positions.size(), original.positions.size());
    std::vector<glm::vec3> world(positions.size());
    for (size_t i = 0; i < positions.size(); ++i) {
      world[i] = glm::vec3(placed * glm::vec4(positions[i], 1.0f));
      const glm::vec3 expected(scene.shapes[shapeIndex].transform * glm::vec4(original.positions[i], 1.0f));
      EXPECT_NEAR(glm::length(world[i] - expected), 0.0f, 1e-5f) << node.name << " vertex " << i;
    }
    // Front faces still face out of the box: the winding survived the mirror.
    const glm::vec3 centre(scene.shapes[shapeIndex].transform * glm::vec4(0, 0, 0, 1));
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
      const glm::vec3 p0 = world[indices[t]], p1 = world[indices[t + 1]], p2 = world[indices[t + 2]];
      EXPECT_GT(glm::dot(glm::cross(p1 - p0, p2 - p0), (p0 + p1 + p2) / 3.0f - centre), 0.0f) << node.name << " " << t;
    }
  }
}

TEST(GltfWriter, ShapesWithoutGeometryAreLeftOut) {
  Scene scene = samples::litBox();
  scene.shapes.push_back(Shape{});                        // no mesh
  scene.shapes.push_back(scene.shapes[0]);
  scene.shapes.back().mesh = std::make_shared<Mesh>();    // no vertices
  scene.shapes.push_back(scene.shapes[0]);
  scene.shapes.back().transform = glm::scale(glm::mat4(1.0f), glm::vec3(1, 0, 1));  // flattened to nothing
  const tinygltf::Model model = writeAndRead(scene, "without_geometry");
  EXPECT_EQ(model.nodes.size(), 1u);
}

}  // namespace
}  // namespace pw::engine
