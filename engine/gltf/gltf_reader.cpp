// The reader's container layer: GLB or JSON, the asset header, required extensions
// and the buffers. gltf_read_scene.cpp turns the document into a Scene.
#include "engine/gltf/gltf_reader.h"

#include <cstring>
#include <set>

#include "base/atomic_file.h"
#include "base/input_file.h"
#include "engine/gltf/gltf_read_scene.h"
#include "engine/gltf/gltf_read_source.h"
#include "engine/scene/model_info.h"

namespace pw::engine {

namespace {

using gltf::Json;
using gltf::Source;

constexpr uint32_t kGlbMagic = 0x46546C67, kChunkJson = 0x4E4F534A, kChunkBin = 0x004E4942;

uint32_t readUint32(const uint8_t* p) {
  return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

// The extensions the reader understands or can safely ignore; a file that requires
// any other cannot be shown correctly.
const std::set<std::string>& knownExtensions() {
  static const std::set<std::string> kKnown = {"KHR_materials_unlit", "KHR_lights_punctual", "KHR_texture_transform",
                                               "KHR_materials_emissive_strength"};
  return kKnown;
}

Status parseJson(Source& source, std::string_view text) {
  try {
    source.doc = Json::parse(text.begin(), text.end());
  } catch (const Json::exception& e) {
    // nlohmann's messages start "[json.exception.parse_error.101] parse error at line
    // 1, column 5: ..."; keep the part a person can use.
    std::string what = e.what();
    if (const size_t bracket = what.find("] "); bracket != std::string::npos) what = what.substr(bracket + 2);
    return source.error("not valid glTF JSON: " + what);
  }
  if (!source.doc.is_object()) return source.error("not valid glTF: the JSON is not an object");
  return {};
}

Status checkAsset(const Source& source) {
  const Json* asset = gltf::member(source.doc, "asset");
  const Json* version = asset ? gltf::member(*asset, "version") : nullptr;
  if (!version || !version->is_string()) return source.error("not glTF: asset.version is missing");
  const std::string v = version->get<std::string>();
  if (v.rfind("2.", 0) != 0) return source.error("glTF version " + v + " is not supported; only 2.x");
  if (const Json* required = gltf::member(source.doc, "extensionsRequired"); required && required->is_array()) {
    for (const Json& name : *required) {
      if (!name.is_string() || !knownExtensions().count(name.get<std::string>())) {
        return source.error("requires the extension " + name.dump() + ", which photowalk cannot read");
      }
    }
  }
  if (const Json* used = gltf::member(source.doc, "extensionsUsed"); used && used->is_array()) {
    for (const Json& name : *used) {
      if (name.is_string() && !knownExtensions().count(name.get<std::string>())) {
        source.warn("ignores the extension " + name.get<std::string>());
      }
    }
  }
  for (const char* ignored : {"animations", "skins"}) {
    if (const Json* items = gltf::member(source.doc, ignored); items && items->is_array() && !items->empty()) {
      source.warn(std::string("ignores its ") + ignored + " (the scene is read as it stands)");
    }
  }
  return {};
}

Status loadBuffers(Source& source, std::span<const uint8_t> glbBin, bool hasGlbBin) {
  const Json* buffers = gltf::member(source.doc, "buffers");
  if (!buffers) return {};
  if (!buffers->is_array()) return source.error("buffers is not an array");
  for (size_t i = 0; i < buffers->size(); ++i) {
    const std::string where = "buffers[" + std::to_string(i) + "]";
    const Json& buffer = (*buffers)[i];
    const Json* length = gltf::member(buffer, "byteLength");
    if (!length || !length->is_number_unsigned() || length->get<size_t>() == 0) {
      return source.error(where + ": byteLength must be a positive integer");
    }
    const size_t byteLength = length->get<size_t>();
    std::vector<uint8_t> bytes;
    if (const Json* uri = gltf::member(buffer, "uri")) {
      if (!uri->is_string()) return source.error(where + ": uri is not a string");
      auto resolved = gltf::resolveUri(source, uri->get<std::string>(), where);
      if (!resolved) return resolved.error();
      bytes = std::move(*resolved);
    } else if (i == 0 && hasGlbBin) {
      bytes.assign(glbBin.begin(), glbBin.end());
    } else {
      return source.error(where + ": has no uri and there is no GLB binary chunk for it");
    }
    if (bytes.size() < byteLength) {
      return source.error(where + ": holds " + std::to_string(bytes.size()) + " bytes, not the " +
                          std::to_string(byteLength) + " its byteLength says");
    }
    bytes.resize(byteLength);
    source.buffers.push_back(std::move(bytes));
  }
  return {};
}

}  // namespace

Result<Scene> parseGltf(std::span<const uint8_t> bytes, const std::filesystem::path& baseDir, std::string_view name,
                        std::vector<std::string>* warnings, const std::vector<std::filesystem::path>& extraFolders) {
  Source source;
  source.baseDir = baseDir;
  source.extraFolders = extraFolders;
  source.name = std::string(name);
  source.warnings = warnings;
  std::span<const uint8_t> bin;
  bool hasBin = false;
  if (bytes.size() >= 4 && readUint32(bytes.data()) == kGlbMagic) {
    // GLB (glTF 2.0, section 4): 12-byte header, a JSON chunk, an optional BIN chunk.
    if (bytes.size() < 20) return source.error("truncated GLB header");
    if (readUint32(bytes.data() + 4) != 2) return source.error("GLB version " + std::to_string(readUint32(bytes.data() + 4)) + " is not 2");
    const uint32_t total = readUint32(bytes.data() + 8);
    if (total < 20) return source.error("malformed GLB: its length field is " + std::to_string(total));
    if (total > bytes.size()) return source.error("truncated GLB: it says " + std::to_string(total) + " bytes, the file has " + std::to_string(bytes.size()));
    const uint32_t jsonLength = readUint32(bytes.data() + 12);
    if (readUint32(bytes.data() + 16) != kChunkJson || jsonLength > total - 20) {
      return source.error("malformed GLB: the first chunk is not a complete JSON chunk");
    }
    PW_TRY(parseJson(source, std::string_view(reinterpret_cast<const char*>(bytes.data() + 20), jsonLength)));
    const size_t binAt = 20 + static_cast<size_t>((jsonLength + 3) & ~3u);
    if (binAt + 8 <= total && readUint32(bytes.data() + binAt + 4) == kChunkBin) {
      const uint32_t binLength = readUint32(bytes.data() + binAt);
      if (binLength > total - binAt - 8) return source.error("truncated GLB: the BIN chunk runs past the end");
      bin = bytes.subspan(binAt + 8, binLength);
      hasBin = true;
    }
  } else {
    PW_TRY(parseJson(source, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size())));
  }
  PW_TRY(checkAsset(source));
  PW_TRY(loadBuffers(source, bin, hasBin));
  try {
    auto scene = gltf::buildScene(source);
    // Detail layers (texture_detail.h): images of the names the info lines give.
    const auto loadDetail = [&source](const std::string& name) -> std::shared_ptr<const Image> {
      const Json* images = gltf::member(source.doc, "images");
      if (!images || !images->is_array()) return nullptr;
      for (size_t i = 0; i < images->size(); ++i) {
        const Json* n = gltf::member((*images)[i], "name");
        if (!n || !n->is_string() || n->get<std::string>() != name) continue;
        auto decoded = gltf::decodeImages(source, {i});
        return decoded.count(i) ? decoded[i].image : nullptr;
      }
      return nullptr;
    };
    if (scene) takeModelInfo(*scene, loadDetail);
    return scene;
  } catch (const Json::exception& e) {
    // Every member is checked before use; this only turns an oversight into an error.
    return source.error(std::string("malformed glTF: ") + e.what());
  }
}

Result<Scene> readGltf(const std::filesystem::path& path, std::vector<std::string>* warnings,
                       const std::vector<std::filesystem::path>& extraFolders) {
  auto bytes = readInputFile(path, kModelInput);
  if (!bytes) return bytes.error();
  return parseGltf(std::span<const uint8_t>(reinterpret_cast<const uint8_t*>(bytes->data()), bytes->size()),
                   path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path(), path.string(), warnings,
                   extraFolders);
}

}  // namespace pw::engine
