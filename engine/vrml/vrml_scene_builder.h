// The VRML97 node tree to photowalk's scene model.
//
// A depth-first walk (iterative, with an explicit stack) accumulates Transforms in
// double precision and emits one scene Shape per Shape node reached, in document
// order. Shared nodes stay shared: the same geometry (with the same texture
// transform) gives the same Mesh pointer, the same Appearance / ImageTexture node the
// same Appearance / Texture pointer, the same image file one decoded Image. Inline and
// EXTERNPROTO files are loaded through a DocumentLoader; their failures are warnings.
#pragma once

#include <filesystem>
#include <memory>

#include "base/result.h"
#include "engine/scene/scene.h"
#include "engine/vrml/diagnostics.h"
#include "engine/vrml/vrml_node.h"

namespace pw::engine::vrml {

class DocumentLoader {
 public:
  virtual ~DocumentLoader() = default;
  // Reads and parses a VRML97 file (cached by the implementation).
  virtual Result<std::shared_ptr<Document>> load(const std::filesystem::path& path) = 0;
};

struct BuildLimits {
  size_t maxShapes = 1000000;          // shapes after DEF/USE and Inline multiplication
  size_t maxVisitedNodes = 20000000;   // nodes walked, counting every USE
  size_t maxProtoCopies = 1000000;     // nodes copied by PROTO expansion
  int maxInlineDepth = 32;
};

Result<Scene> buildScene(const std::shared_ptr<Document>& document, DocumentLoader& loader, Diagnostics* diagnostics,
                         const BuildLimits& limits = {});

}  // namespace pw::engine::vrml
