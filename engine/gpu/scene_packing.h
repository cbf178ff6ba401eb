// Flattening a Scene into what the GPU draws: one vertex and one index buffer for the
// whole scene (meshes shared by several shapes are stored once), one ShapeGpu per
// drawn shape, the lights, and the draw lists. Pure CPU work, tested without Vulkan.
#pragma once

#include <array>
#include <optional>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "base/result.h"
#include "engine/scene/scene.h"
#include "shaders/shader_interface.h"

namespace pw::engine::gpu {

// One interleaved vertex (binding 0; locations in shader_interface.h).
struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec2 texCoord;  // VRML (s, t): t = 0 at the bottom; the vertex shader flips it
  glm::vec4 color;     // linear RGBA (white when the mesh has no colours)
};
static_assert(sizeof(Vertex) == 48);

// Pipelines differ in topology, blending and the fragment shader's specialization
// (texturing, lighting); culling and winding are dynamic state.
struct PipelineVariant {
  Topology topology = Topology::kTriangles;
  bool blended = false;   // transparent: alpha blending, no depth writes, drawn back to front
  bool textured = false;  // PW_SPEC_TEXTURED
  bool lit = true;        // PW_SPEC_LIT
  bool photoTexture = false;  // PW_SPEC_PHOTO_TEXTURE: the texture was cut from a photo
  int index() const {
    return (((static_cast<int>(topology) * 2 + blended) * 2 + textured) * 2 + lit) * 2 + photoTexture;
  }
  static constexpr int kCount = 48;
};

struct DrawItem {
  uint32_t shapeIndex = 0;  // into PackedScene::shapes and the push constant
  MaterialGpu material{};   // pushed with the draw
  uint32_t firstIndex = 0;
  uint32_t indexCount = 0;
  int32_t vertexOffset = 0;
  uint32_t textureSlot = 0;  // 0: none (a 1x1 white texture), else PackedScene::textures[slot - 1]
  std::array<glm::vec4, 3> textureSource{};  // pushed with the draw (DrawPushConstants::textureSource)
  uint32_t lightListOffset = 0;  // DrawPushConstants: the lights that reach the shape
  uint32_t pointLightCount = 0;
  uint32_t spotLightCount = 0;
  PipelineVariant variant;
  bool cullBackFaces = true;      // solid TRUE
  bool clockwiseFront = false;    // a mirroring transform (negative determinant) flips the winding
  Bounds worldBounds;
};

struct PackedTexture {
  const Texture* texture = nullptr;  // borrowed from the Scene for the duration of the upload
  bool hasAlpha = false;              // some texel has alpha < 255
  // Drawn as cut from a photo (an opaque texture with a usable source): uploaded as its
  // base with the detail code in alpha (texture_detail.h, stageBaseAndDetail).
  bool cutFromPhoto = false;
};

struct PackedScene {
  std::vector<Vertex> vertices;
  std::vector<uint32_t> indices;
  std::vector<ShapeGpu> shapes;
  std::vector<LightGpu> lights;                // the lights that are on: directional, point, spot
  glm::uvec3 lightCounts{0};                   // how many of each kind, in that order
  std::vector<uint32_t> lightLists;            // per lit draw: indices of its point, then spot lights
  std::vector<PackedTexture> textures;         // distinct Texture objects, in slot order
  std::vector<DrawItem> opaque;                // sorted by pipeline, texture, cull state
  std::vector<DrawItem> transparent;           // sorted per frame, back to front
  glm::vec3 backgroundLinear{0.0f};
};

// Errors name the shape (or texture) and what is wrong with it: indices out of range,
// attribute arrays of the wrong length, a texture without pixels, non-finite numbers.
// Shapes without a mesh or with nothing to draw are skipped.
Result<PackedScene> packScene(const Scene& scene);

// DrawPushConstants::textureSource for a texture: its Texture::sourceFromTexCoord
// taken to the shader's texture coordinates (v = 1 - t), with the texture's size; none
// without one, or with one that is not finite or puts part of the texture behind the
// photo's camera (the texture is then drawn as any other).
std::optional<std::array<glm::vec4, 3>> textureSourceColumns(const Texture& texture);

// The inverse transpose of the upper 3x3, computed as the cofactor matrix so that
// singular transforms (a zero scale) still give finite normals; the shader normalises.
glm::mat3 normalMatrix(const glm::mat4& model);

}  // namespace pw::engine::gpu
