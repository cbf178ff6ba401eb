// Appearance, Material, ImageTexture / PixelTexture and TextureTransform nodes to the
// scene's shared Appearance and Texture objects (ISO/IEC 14772-1, 6.3, 6.27, 6.22,
// 6.33, 6.53).
#pragma once

#include <memory>
#include <string>
#include <unordered_map>

#include "base/result.h"
#include "engine/scene/scene.h"
#include "engine/vrml/diagnostics.h"
#include "engine/vrml/vrml_geometry.h"
#include "engine/vrml/vrml_node.h"

namespace pw::engine::vrml {

struct ShapeLook {
  std::shared_ptr<const Appearance> appearance;  // null: no Appearance node
  const Node* textureTransform = nullptr;        // set only when there is a usable texture
};

class AppearanceBuilder {
 public:
  AppearanceBuilder(NodeResolver resolve, Diagnostics* diagnostics)
      : resolve_(std::move(resolve)), diagnostics_(diagnostics) {}

  // The look of a Shape's appearance field (cached per Appearance node, so that
  // DEF/USE of an appearance gives the same pointer).
  Result<ShapeLook> look(const NodePtr& appearanceField);

 private:
  Result<std::shared_ptr<const Texture>> texture(const Node& node);
  std::shared_ptr<const Image> loadImageFile(const Node& node, std::string& usedUrl);

  NodeResolver resolve_;
  Diagnostics* diagnostics_;
  std::unordered_map<const Node*, ShapeLook> looks_;
  std::unordered_map<const Node*, std::shared_ptr<const Texture>> textures_;
  std::unordered_map<std::string, std::shared_ptr<const Image>> images_;  // by resolved path
};

// Tc' = -C × S × R × C × T × Tc (6.53), as a 2D homogeneous matrix.
glm::dmat3 textureTransformMatrix(const Node& textureTransform);

// Material node fields, clamped to the ranges the standard gives.
Material materialFromNode(const Node& node);

// A url of an ImageTexture / Inline / EXTERNPROTO in `file` as a local path: relative
// urls against its folder, "file:" urls as paths; nullopt (with the reason, which
// quotes the url but nothing of the file) for remote urls and for paths outside the
// folders the file may read (SourceFile::folders): absolute, `..` out of it, a link
// leading out.
std::optional<std::filesystem::path> localPath(const std::string& url, const SourceFile* file, std::string& whyNot);

}  // namespace pw::engine::vrml
