// Test helper: reads a written glTF file back with tinygltf (a second, independent
// reader) and pulls accessor data out as plain vectors.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

// Every file that includes tiny_gltf.h must see the same options (they change the
// TinyGLTF class). stb_image's implementation lives in pw_scene, so tinygltf's own
// stb use is off and images are decoded through engine/scene/image.h.
#ifndef TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE
#endif
#ifndef TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#endif
#ifndef TINYGLTF_NO_EXTERNAL_IMAGE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#endif
#include <tiny_gltf.h>

#include "base/result.h"

namespace pw::engine::testing {

// Parses .glb or .gltf bytes. Embedded PNGs are decoded (to RGBA8) with
// engine/scene/image.h, since stb_image's implementation lives in pw_scene.
Result<tinygltf::Model> parseGltf(const std::vector<uint8_t>& bytes, bool binary);
Result<tinygltf::Model> readGltfFile(const std::filesystem::path& path);

// Elements of a float accessor (VEC2/VEC3/VEC4), and of an index accessor.
std::vector<glm::vec2> readVec2(const tinygltf::Model& model, int accessor);
std::vector<glm::vec3> readVec3(const tinygltf::Model& model, int accessor);
std::vector<glm::vec4> readVec4(const tinygltf::Model& model, int accessor);
std::vector<uint32_t> readIndices(const tinygltf::Model& model, int accessor);

// Where the tests write their files: PW_BINARY_DIR/tests/gltf/out, or $PW_GLTF_TEST_OUT
// (the validator ctest re-runs the tests into its own folder and checks every file).
std::filesystem::path outputDir();

}  // namespace pw::engine::testing
