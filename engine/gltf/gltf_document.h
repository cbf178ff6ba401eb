// Internal to pw_gltf: builds the glTF JSON document and its binary buffer from a
// Scene. gltf_writer.cpp packs the result into a .glb or .gltf file.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/result.h"
#include "engine/scene/scene.h"

namespace pw::engine::gltf {

using Json = nlohmann::json;

// glTF accessor component types and buffer view targets (glTF 2.0, 5.1.2 and 5.11).
inline constexpr int kComponentUint16 = 5123;
inline constexpr int kComponentUint32 = 5125;
inline constexpr int kComponentFloat = 5126;
inline constexpr int kTargetArrayBuffer = 34962;
inline constexpr int kTargetElementArrayBuffer = 34963;

// `mesh` with `transform` applied to its vertices, for shapes whose transform glTF
// cannot hold as a node's TRS (shear, projection). Nothing when the transform is
// singular and the mesh is made of triangles: the shape has no area to draw.
std::optional<Mesh> bakeTransform(const Mesh& mesh, const glm::mat4& transform);

// `mesh` reflected in its local x = 0 plane, with the triangle winding reversed so
// that front faces stay front faces. A shape whose transform mirrors (negative
// determinant) is written as this mesh under the transform times that reflection.
Mesh mirroredInX(const Mesh& mesh);

class DocumentBuilder {
 public:
  // jpegQuality 1..100: opaque textures as JPEG of that quality (0: every one PNG).
  explicit DocumentBuilder(const Scene& scene, int jpegQuality = 0) : scene_(scene), jpegQuality_(jpegQuality) {}

  // Fills document() and binary(); call once.
  Status build();

  Json& document() { return doc_; }
  const std::vector<uint8_t>& binary() const { return bin_; }

 private:
  // Accessors of one mesh's vertex data, made on first use and shared by every
  // shape and material that draws it.
  struct MeshData {
    int position = -1;
    int normal = -1;
    int color = -1;
    int texCoord = -1;
    int indices = -1;  // -1: non-indexed (points without indices)
    bool translucentColors = false;
  };
  struct ImageSlot {
    std::shared_ptr<const Image> image;
    int index = -1;
  };

  Status addShape(size_t shapeIndex);
  Status addCamera(const Viewpoint& viewpoint, size_t viewpointIndex);
  Status addLight(const Light& light, size_t lightIndex);
  int addRootNode(Json node);

  // gltf_geometry.cpp
  Result<int> meshFor(const Mesh& mesh, const Appearance* appearance, const std::string& shapeLabel);
  Result<MeshData*> meshDataFor(const Mesh& mesh, const std::string& shapeLabel);
  int texCoordsFor(const Mesh& mesh, MeshData& data);
  int addView(const void* bytes, size_t size, std::optional<int> target);
  int addAccessor(int view, int componentType, size_t count, const char* type, Json min = {}, Json max = {});

  // gltf_materials.cpp
  int materialFor(const Appearance* appearance, const Mesh& mesh, const MeshData& data);
  int textureFor(const Texture& texture);
  int imageFor(const std::shared_ptr<const Image>& image);
  bool imageHasAlpha(const Image& image);
  // Encodes the images (in parallel) and appends them to the buffer; after the geometry,
  // so that vertex data stays at the start of the buffer.
  Status embedImages();

  int addExtensionUsed(const char* name);

  const Scene& scene_;
  int jpegQuality_ = 0;
  Json doc_ = Json::object();
  std::vector<uint8_t> bin_;

  std::map<const Mesh*, MeshData> meshData_;
  std::map<std::pair<const Mesh*, int>, int> meshes_;  // (mesh, material) -> glTF mesh
  std::map<std::string, int> materials_;               // material JSON text -> index
  std::map<std::pair<int, int>, int> textures_;         // (image, sampler) -> index
  std::map<std::pair<int, int>, int> samplers_;         // (wrapS, wrapT) -> index
  std::map<const Image*, int> images_;
  std::map<const Image*, bool> imageAlpha_;
  std::vector<ImageSlot> pendingImages_;
  std::vector<std::unique_ptr<Mesh>> bakedMeshes_;  // shapes whose transform has shear
  std::map<const Mesh*, std::unique_ptr<Mesh>> mirroredMeshes_;  // one per mesh drawn mirrored
  std::vector<int> rootNodes_;
};

}  // namespace pw::engine::gltf
