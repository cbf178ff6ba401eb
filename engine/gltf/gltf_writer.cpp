// Packs the document into a file: GLB (glTF 2.0, section 4) or .gltf with a data: URI.
#include "engine/gltf/gltf_writer.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <limits>
#include <span>
#include <string>
#include <string_view>

#include "base/atomic_file.h"
#include "base/base64.h"
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

// The GLB header, the JSON chunk and the BIN chunk's header: everything but the
// binary data itself, which follows unchanged (it is already padded to 4 bytes).
Result<std::vector<uint8_t>> glbHead(const gltf::Json& doc, const std::vector<uint8_t>& bin) {
  std::string json = dumpJson(doc);
  json.resize((json.size() + 3) & ~size_t{3}, ' ');  // the JSON chunk pads with spaces
  const size_t total =
      kGlbHeaderBytes + kChunkHeaderBytes + json.size() + (bin.empty() ? 0 : kChunkHeaderBytes + bin.size());
  if (total > std::numeric_limits<uint32_t>::max()) {
    return makeError("the scene needs " + std::to_string(total >> 20) + " MiB, more than a GLB file can hold (4 GiB)");
  }
  std::vector<uint8_t> head;
  head.reserve(kGlbHeaderBytes + 2 * kChunkHeaderBytes + json.size());
  appendUint32(head, kGlbMagic);
  appendUint32(head, kGlbVersion);
  appendUint32(head, static_cast<uint32_t>(total));
  appendUint32(head, static_cast<uint32_t>(json.size()));
  appendUint32(head, kChunkJson);
  head.insert(head.end(), json.begin(), json.end());
  if (!bin.empty()) {
    appendUint32(head, static_cast<uint32_t>(bin.size()));
    appendUint32(head, kChunkBin);
  }
  return head;
}

std::vector<uint8_t> packEmbeddedJson(gltf::Json& doc, const std::vector<uint8_t>& bin) {
  if (bin.empty()) {
    const std::string json = dumpJson(doc);
    return std::vector<uint8_t>(json.begin(), json.end());
  }
  // The data URI is spliced into the dumped text rather than put in the JSON value:
  // nlohmann would copy and scan its megabytes several times. The empty "uri" is the
  // only one in the document, and `"uri":""` cannot come from a string's content,
  // whose quotes are always escaped.
  static constexpr std::string_view kPrefix = "data:application/octet-stream;base64,";
  doc["buffers"][0]["uri"] = "";
  const std::string json = dumpJson(doc);
  const size_t slot = json.find("\"uri\":\"\"") + 7;  // between the two quotes
  const size_t encodedSize = base64Size(bin.size());
  std::vector<uint8_t> out(json.size() + kPrefix.size() + encodedSize);
  std::memcpy(out.data(), json.data(), slot);
  std::memcpy(out.data() + slot, kPrefix.data(), kPrefix.size());
  base64Into(bin, reinterpret_cast<char*>(out.data() + slot + kPrefix.size()));
  std::memcpy(out.data() + slot + kPrefix.size() + encodedSize, json.data() + slot, json.size() - slot);
  return out;
}

}  // namespace

Result<std::vector<uint8_t>> encodeGltf(const Scene& scene, GltfContainer container, int jpegQuality) {
  gltf::DocumentBuilder builder(scene, jpegQuality);
  PW_TRY(builder.build());
  if (container == GltfContainer::kEmbeddedJson) return packEmbeddedJson(builder.document(), builder.binary());
  auto head = glbHead(builder.document(), builder.binary());
  if (!head) return head.error();
  head->insert(head->end(), builder.binary().begin(), builder.binary().end());
  return head;
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
  gltf::DocumentBuilder builder(scene);
  if (Status built = builder.build(); !built) return makeError(out.string() + ": " + built.message());
  std::vector<uint8_t> head;
  std::span<const uint8_t> tail;  // the GLB's binary data, written straight from the builder
  if (extension == ".glb") {
    auto glb = glbHead(builder.document(), builder.binary());
    if (!glb) return makeError(out.string() + ": " + glb.message());
    head = std::move(*glb);
    tail = builder.binary();
  } else {
    head = packEmbeddedJson(builder.document(), builder.binary());
  }
  return writeViaTempFile(out, [&](const std::filesystem::path& temp) -> Status {
    std::ofstream file(temp, std::ios::binary | std::ios::trunc);
    if (!file) return makeError(out.string() + ": cannot write: " + std::strerror(errno));
    file.write(reinterpret_cast<const char*>(head.data()), static_cast<std::streamsize>(head.size()));
    file.write(reinterpret_cast<const char*>(tail.data()), static_cast<std::streamsize>(tail.size()));
    file.flush();
    if (!file) return makeError(out.string() + ": write failed (disk full?)");
    return {};
  });
}

}  // namespace pw::engine
