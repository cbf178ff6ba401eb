// Packs the document into a file: GLB (glTF 2.0, section 4) or .gltf with a data: URI.
#include "engine/gltf/gltf_writer.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <limits>
#include <string>

#include "base/atomic_file.h"
#include "engine/gltf/gltf_document.h"

namespace pw::engine {

namespace {

constexpr uint32_t kGlbMagic = 0x46546C67;      // "glTF"
constexpr uint32_t kGlbVersion = 2;
constexpr uint32_t kChunkJson = 0x4E4F534A;     // "JSON"
constexpr uint32_t kChunkBin = 0x004E4942;      // "BIN\0"
constexpr size_t kGlbHeaderBytes = 12;
constexpr size_t kChunkHeaderBytes = 8;

void appendUint32(std::vector<uint8_t>& out, uint32_t value) {
  // GLB is little-endian, like every machine photowalk runs on; spelled out anyway.
  for (int shift = 0; shift < 32; shift += 8) out.push_back(static_cast<uint8_t>(value >> shift));
}

// Strings from VRML files may hold bytes that are not UTF-8; JSON must be UTF-8, so
// such bytes become U+FFFD rather than making the export fail.
std::string dumpJson(const gltf::Json& doc) { return doc.dump(-1, ' ', false, gltf::Json::error_handler_t::replace); }

std::string base64(const std::vector<uint8_t>& bytes) {
  static const char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const uint32_t v = uint32_t(bytes[i]) << 16 | uint32_t(bytes[i + 1]) << 8 | bytes[i + 2];
    out += {kAlphabet[v >> 18], kAlphabet[(v >> 12) & 63], kAlphabet[(v >> 6) & 63], kAlphabet[v & 63]};
  }
  if (i + 1 == bytes.size()) {
    const uint32_t v = uint32_t(bytes[i]) << 16;
    out += {kAlphabet[v >> 18], kAlphabet[(v >> 12) & 63], '=', '='};
  } else if (i + 2 == bytes.size()) {
    const uint32_t v = uint32_t(bytes[i]) << 16 | uint32_t(bytes[i + 1]) << 8;
    out += {kAlphabet[v >> 18], kAlphabet[(v >> 12) & 63], kAlphabet[(v >> 6) & 63], '='};
  }
  return out;
}

Result<std::vector<uint8_t>> packGlb(const gltf::Json& doc, const std::vector<uint8_t>& bin) {
  std::string json = dumpJson(doc);
  json.resize((json.size() + 3) & ~size_t{3}, ' ');  // the JSON chunk pads with spaces
  const size_t total = kGlbHeaderBytes + kChunkHeaderBytes + json.size() + (bin.empty() ? 0 : kChunkHeaderBytes + bin.size());
  if (total > std::numeric_limits<uint32_t>::max()) {
    return makeError("the scene needs " + std::to_string(total >> 20) + " MiB, more than a GLB file can hold (4 GiB)");
  }
  std::vector<uint8_t> out;
  out.reserve(total);
  appendUint32(out, kGlbMagic);
  appendUint32(out, kGlbVersion);
  appendUint32(out, static_cast<uint32_t>(total));
  appendUint32(out, static_cast<uint32_t>(json.size()));
  appendUint32(out, kChunkJson);
  out.insert(out.end(), json.begin(), json.end());
  if (!bin.empty()) {  // bin is already padded to 4 bytes with zeros
    appendUint32(out, static_cast<uint32_t>(bin.size()));
    appendUint32(out, kChunkBin);
    out.insert(out.end(), bin.begin(), bin.end());
  }
  return out;
}

std::vector<uint8_t> packEmbeddedJson(gltf::Json& doc, const std::vector<uint8_t>& bin) {
  if (!bin.empty()) doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(bin);
  const std::string json = dumpJson(doc);
  return std::vector<uint8_t>(json.begin(), json.end());
}

}  // namespace

Result<std::vector<uint8_t>> encodeGltf(const Scene& scene, GltfContainer container) {
  gltf::DocumentBuilder builder(scene);
  PW_TRY(builder.build());
  if (container == GltfContainer::kGlb) return packGlb(builder.document(), builder.binary());
  return packEmbeddedJson(builder.document(), builder.binary());
}

Status writeGltf(const Scene& scene, const std::filesystem::path& out) {
  std::string extension = out.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  if (extension != ".glb" && extension != ".gltf") {
    return makeError(out.string() + ": unknown glTF file type '" + extension + "'; name it .glb (binary) or .gltf");
  }
  // Check the folder before the (slow) encoding, so a typo fails at once.
  std::error_code ec;
  if (out.has_parent_path() && !std::filesystem::is_directory(out.parent_path(), ec)) {
    return makeError(out.string() + ": the folder " + out.parent_path().string() + " does not exist");
  }
  auto bytes = encodeGltf(scene, extension == ".glb" ? GltfContainer::kGlb : GltfContainer::kEmbeddedJson);
  if (!bytes) return makeError(out.string() + ": " + bytes.message());
  return writeFileAtomic(out, std::span<const char>(reinterpret_cast<const char*>(bytes->data()), bytes->size()));
}

}  // namespace pw::engine
