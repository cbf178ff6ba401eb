// Reading a model for the commands that draw or convert one (render, walk, export).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "base/result.h"
#include "engine/scene/scene.h"

namespace pw::engine {

// The name of the built-in sample room (engine/scene/sample_scene.h).
inline constexpr const char* kSampleSceneName = "sample";

// Loads `path` as a scene: "sample" is the built-in room; other files by their format.
// Non-fatal problems (an ignored node, a texture that fell back to a colour) are
// appended to `warnings` (may be null) as one-line messages.
// The model's own files (Inlines, textures, buffers) are read only from inside its
// folder and `extraFolders` (README: What photowalk reads).
Result<Scene> loadModel(const std::filesystem::path& path, std::vector<std::string>* warnings,
                        const std::vector<std::filesystem::path>& extraFolders = {});

}  // namespace pw::engine
