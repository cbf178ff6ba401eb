// glTF 2.0 import into the scene model (engine/scene/scene.h): the reverse of
// gltf_writer.h, for models made elsewhere and for checking what photowalk wrote.
//
// Reads .glb and .gltf (buffers and images embedded as data: URIs, in the GLB's BIN
// chunk or in files beside the .gltf). The node tree is flattened: each mesh
// primitive of each node becomes a Shape with the node's world transform, sharing
// one Mesh and Appearance per primitive between all nodes that use it. Materials
// map back to VRML ones (gltf_mapping.h: sRGB colours, shininess from roughness);
// KHR_materials_unlit gives an Appearance without Material; perspective cameras
// become Viewpoints and KHR_lights_punctual lights become Lights. Animations,
// skins, morph targets, orthographic cameras and texture transforms are ignored
// (each with a warning); a file that requires an extension photowalk cannot read
// (Draco, meshopt, Basis textures) is an error.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "base/result.h"
#include "engine/scene/scene.h"

namespace pw::engine {

// Errors (one line, naming the file and the JSON path where it helps): unreadable or
// truncated files, malformed JSON or GLB, references out of range, accessors that
// do not fit their buffers, non-finite vertex data, node loops, a required unknown
// extension. What still leaves a usable scene (an image that cannot be decoded, an
// ignored feature) is appended to `warnings` (may be null).
// Buffers and images are read only from inside the file's folder and `extraFolders`.
Result<Scene> readGltf(const std::filesystem::path& path, std::vector<std::string>* warnings = nullptr,
                       const std::vector<std::filesystem::path>& extraFolders = {});

// The same for bytes in memory; relative URIs resolve against `baseDir` (empty: they
// are refused). `name` stands for the file in messages.
Result<Scene> parseGltf(std::span<const uint8_t> bytes, const std::filesystem::path& baseDir, std::string_view name,
                        std::vector<std::string>* warnings = nullptr,
                        const std::vector<std::filesystem::path>& extraFolders = {});

}  // namespace pw::engine
