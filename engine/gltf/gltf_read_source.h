// Internal to pw_gltf's reader: the parsed document, its loaded buffers, and checked
// access to JSON members and accessor data (every index and range is checked: the
// input is a file from anywhere).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "base/result.h"
#include "engine/scene/scene.h"

namespace pw::engine::gltf {

using Json = nlohmann::json;

struct Source {
  Json doc;
  std::vector<std::vector<uint8_t>> buffers;
  std::filesystem::path baseDir;  // empty: relative URIs are refused
  // Besides baseDir, folders a URI may lead into (README: What photowalk reads).
  std::vector<std::filesystem::path> extraFolders;
  std::string name;               // the file, for messages
  std::vector<std::string>* warnings = nullptr;

  Error error(const std::string& what) const { return makeError(name + ": " + what); }
  void warn(const std::string& what) const {
    if (warnings) warnings->push_back(name + ": " + what);
  }
};

// The member `key` of `object`, or null when `object` is not an object or lacks it.
const Json* member(const Json& object, const char* key);
// The element `index` of the top-level array `arrayName` ("meshes", ...).
Result<const Json*> element(const Source& source, const char* arrayName, const Json& index, const std::string& where);
// A number member, `fallback` when absent; an error when present but not a finite number.
Result<double> numberOr(const Source& source, const Json& object, const char* key, double fallback,
                        const std::string& where);
// Numbers of an array member of fixed length; `fallback` when absent.
Result<std::vector<double>> numbersOr(const Source& source, const Json& object, const char* key, size_t length,
                                      std::vector<double> fallback, const std::string& where);

// The bytes a URI names: a base64 data: URI, or a file relative to source.baseDir.
Result<std::vector<uint8_t>> resolveUri(const Source& source, const std::string& uri, const std::string& where);
// Bytes of a bufferView.
Result<std::span<const uint8_t>> bufferViewBytes(const Source& source, const Json& index, const std::string& where);

// Accessor data, converted to float (normalized integers to [0, 1]) or to indices.
// `components` is what the caller needs (a VEC3 is read as 3, a VEC3 colour may be
// read as 4 with alpha 1); `allowIntegers` admits normalized unsigned byte/short.
Result<std::vector<glm::vec4>> readFloatAccessor(const Source& source, const Json& index, int minComponents,
                                                 int maxComponents, bool allowIntegers, const std::string& where);
Result<std::vector<uint32_t>> readIndexAccessor(const Source& source, const Json& index, size_t vertexCount,
                                                const std::string& where);

// gltf_read_scene.cpp: the scene of a loaded document (source.buffers filled).
Result<Scene> buildScene(const Source& source);

}  // namespace pw::engine::gltf
