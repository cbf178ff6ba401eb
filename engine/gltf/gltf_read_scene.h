// Internal to pw_gltf's reader: the builder that turns a loaded document into a
// Scene. gltf_read_scene.cpp: nodes, meshes, cameras, lights;
// gltf_read_materials.cpp: materials, textures and image decoding.
#pragma once

#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "engine/gltf/gltf_read_source.h"
#include "engine/scene/scene.h"

namespace pw::engine::gltf {

inline std::string indexed(const char* array, size_t i) {
  return std::string(array) + "[" + std::to_string(i) + "]";
}

inline glm::vec3 vec3Of(const std::vector<double>& v) {
  return glm::vec3(static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]));
}

struct DecodedImage {
  std::shared_ptr<const Image> image;  // null when it could not be read (warned)
  std::string url;                     // the file it came from, or its name
};

// Decodes every image that a material's baseColorTexture uses, on all cores: PNG and
// JPEG decoding is most of the reader's time on a textured model (bench/gltf_bench.cpp).
std::map<size_t, DecodedImage> decodeUsedImages(const Source& source);
// The same for the images `used` lists (by index).
std::map<size_t, DecodedImage> decodeImages(const Source& source, const std::set<size_t>& used);

class SceneBuilder {
 public:
  explicit SceneBuilder(const Source& source) : source_(source) {}
  Result<Scene> build();

 private:
  struct Look {
    std::shared_ptr<const Appearance> appearance;
    int texCoordSet = 0;
    bool unlit = false;
    bool doubleSided = false;
    glm::vec4 colorFactor{1.0f};  // folded into vertex colours for unlit, untextured shapes
  };

  Status addNode(size_t index, const glm::mat4& parent, size_t depth);
  Result<glm::mat4> localMatrix(const Json& node, const std::string& where);
  Status addMeshShapes(const Json& meshIndex, const glm::mat4& world, const std::string& nodeName,
                       const std::string& where);
  Result<std::shared_ptr<const Mesh>> primitiveMesh(size_t mesh, size_t primitive, const Json& json, const Look& look,
                                                    const std::string& where);
  Result<Look> lookFor(const Json* materialIndex, const std::string& where);
  std::shared_ptr<const Texture> textureFor(const Json& textureInfo, bool opaque, const std::string& where);
  Status addCamera(const Json& cameraIndex, const glm::mat4& world, const std::string& nodeName,
                   const std::string& where);
  Status addLight(const Json& lightIndex, const glm::mat4& world, const std::string& where);

  const Source& source_;
  Scene scene_;
  std::set<size_t> visited_;
  std::map<std::pair<size_t, size_t>, std::shared_ptr<const Mesh>> meshes_;
  std::map<int, Look> looks_;  // -1: the default material
  std::map<std::pair<size_t, bool>, std::shared_ptr<const Texture>> textures_;
  std::map<std::pair<size_t, bool>, std::shared_ptr<const Image>> images_;
  std::map<size_t, DecodedImage> decoded_;  // every image a material uses, decoded up front
};

}  // namespace pw::engine::gltf
