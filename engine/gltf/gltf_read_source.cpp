// Checked access to a glTF document and its binary data (the reader's untrusted input).
#include "engine/gltf/gltf_read_source.h"

#include <cctype>
#include <cmath>
#include <cstring>
#include <limits>

#include "base/atomic_file.h"
#include "base/input_file.h"

namespace pw::engine::gltf {

namespace {

constexpr int kByte = 5120, kUnsignedByte = 5121, kShort = 5122, kUnsignedShort = 5123, kUnsignedInt = 5125,
              kFloat = 5126;

int componentBytes(int componentType) {
  switch (componentType) {
    case kByte:
    case kUnsignedByte: return 1;
    case kShort:
    case kUnsignedShort: return 2;
    case kUnsignedInt:
    case kFloat: return 4;
    default: return 0;
  }
}

int componentCount(const std::string& type) {
  if (type == "SCALAR") return 1;
  if (type == "VEC2") return 2;
  if (type == "VEC3") return 3;
  if (type == "VEC4") return 4;
  return 0;  // matrices: never vertex attributes photowalk reads
}

int base64Value(unsigned char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}

std::optional<std::vector<uint8_t>> decodeBase64(std::string_view text) {
  std::vector<uint8_t> out;
  out.reserve(text.size() / 4 * 3);
  uint32_t bits = 0;
  int bitCount = 0;
  size_t padding = 0;
  for (unsigned char c : text) {
    if (c == '=') {
      ++padding;
      continue;
    }
    const int value = base64Value(c);
    if (value < 0 || padding > 0) return std::nullopt;  // a stray character, or data after '='
    bits = (bits << 6) | static_cast<uint32_t>(value);
    bitCount += 6;
    if (bitCount >= 8) {
      bitCount -= 8;
      out.push_back(static_cast<uint8_t>(bits >> bitCount));
    }
  }
  if (padding > 2) return std::nullopt;
  return out;
}

// "%20" and the like in relative URIs (RFC 3986, 2.1).
std::string percentDecoded(const std::string& uri) {
  std::string out;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
      out.push_back(static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16)));
      i += 2;
    } else {
      out.push_back(uri[i]);
    }
  }
  return out;
}

float componentValue(const uint8_t* p, int componentType) {
  switch (componentType) {
    case kUnsignedByte: return p[0] / 255.0f;
    case kUnsignedShort: {
      uint16_t v;
      std::memcpy(&v, p, 2);
      return v / 65535.0f;
    }
    case kByte: return std::max(static_cast<int8_t>(p[0]) / 127.0f, -1.0f);
    case kShort: {
      int16_t v;
      std::memcpy(&v, p, 2);
      return std::max(v / 32767.0f, -1.0f);
    }
    default: {
      float v;
      std::memcpy(&v, p, 4);
      return v;
    }
  }
}

struct AccessorLayout {
  const uint8_t* data = nullptr;  // null: all zeros (no bufferView)
  size_t count = 0;
  size_t stride = 0;
  int components = 0;
  int componentType = 0;
  bool normalized = false;
};

Result<AccessorLayout> accessorLayout(const Source& source, const Json& index, const std::string& where) {
  auto accessor = element(source, "accessors", index, where);
  if (!accessor) return accessor.error();
  const Json& a = **accessor;
  const std::string at = where + " (accessor " + index.dump() + ")";
  AccessorLayout layout;
  const Json* type = member(a, "type");
  const Json* componentType = member(a, "componentType");
  const Json* count = member(a, "count");
  if (!type || !type->is_string() || !componentType || !componentType->is_number_integer() || !count ||
      !count->is_number_unsigned()) {
    return source.error(at + ": type, componentType and count are required");
  }
  layout.components = componentCount(type->get<std::string>());
  layout.componentType = componentType->get<int>();
  const int bytes = componentBytes(layout.componentType);
  if (layout.components == 0 || bytes == 0) return source.error(at + ": unsupported type " + type->dump());
  layout.count = count->get<size_t>();
  if (layout.count == 0) return source.error(at + ": count is 0");
  if (const Json* normalized = member(a, "normalized"); normalized && normalized->is_boolean()) {
    layout.normalized = normalized->get<bool>();
  }
  if (member(a, "sparse")) return source.error(at + ": sparse accessors are not supported");
  const size_t elementBytes = static_cast<size_t>(bytes) * layout.components;
  const Json* viewIndex = member(a, "bufferView");
  if (!viewIndex) {
    // No bufferView: every element is zero (glTF 2.0, 3.6.2.3). Cap the count so a
    // tiny file cannot ask for gigabytes.
    if (layout.count > (size_t{1} << 26)) return source.error(at + ": count " + count->dump() + " without data");
    layout.stride = elementBytes;
    return layout;
  }
  auto viewBytes = bufferViewBytes(source, *viewIndex, at);
  if (!viewBytes) return viewBytes.error();
  auto view = element(source, "bufferViews", *viewIndex, at);
  if (!view) return view.error();
  auto offset = numberOr(source, a, "byteOffset", 0, at);
  auto stride = numberOr(source, **view, "byteStride", 0, at);
  if (!offset) return offset.error();
  if (!stride) return stride.error();
  if (*offset < 0 || *stride < 0 || *stride > 252 || std::fmod(*offset, bytes) != 0) {
    return source.error(at + ": byteOffset or byteStride is out of range or misaligned");
  }
  layout.stride = *stride > 0 ? static_cast<size_t>(*stride) : elementBytes;
  if (layout.stride < elementBytes) return source.error(at + ": byteStride is smaller than one element");
  const size_t start = static_cast<size_t>(*offset);
  // start + (count - 1) * stride + elementBytes <= view size, without overflow.
  const size_t available = viewBytes->size();
  if (start > available || elementBytes > available - start ||
      (layout.count - 1) > (available - start - elementBytes) / layout.stride) {
    return source.error(at + ": " + std::to_string(layout.count) + " elements do not fit in its bufferView of " +
                        std::to_string(available) + " bytes");
  }
  layout.data = viewBytes->data() + start;
  return layout;
}

}  // namespace

const Json* member(const Json& object, const char* key) {
  if (!object.is_object()) return nullptr;
  const auto found = object.find(key);
  return found == object.end() ? nullptr : &*found;
}

Result<const Json*> element(const Source& source, const char* arrayName, const Json& index, const std::string& where) {
  const Json* array = member(source.doc, arrayName);
  if (!index.is_number_unsigned()) return source.error(where + ": " + arrayName + " index " + index.dump() + " is not an index");
  const size_t i = index.get<size_t>();
  if (!array || !array->is_array() || i >= array->size()) {
    return source.error(where + ": refers to " + arrayName + "[" + std::to_string(i) + "], which does not exist");
  }
  const Json& item = (*array)[i];
  if (!item.is_object()) return source.error(std::string(arrayName) + "[" + std::to_string(i) + "] is not an object");
  return &item;
}

Result<double> numberOr(const Source& source, const Json& object, const char* key, double fallback,
                        const std::string& where) {
  const Json* value = member(object, key);
  if (!value) return fallback;
  // Within float range too: the scene model is float, and converting a larger double
  // to float is undefined behaviour.
  if (!value->is_number() || !(std::abs(value->get<double>()) <= std::numeric_limits<float>::max())) {
    return source.error(where + ": " + key + " is not a finite number");
  }
  return value->get<double>();
}

Result<std::vector<double>> numbersOr(const Source& source, const Json& object, const char* key, size_t length,
                                      std::vector<double> fallback, const std::string& where) {
  const Json* value = member(object, key);
  if (!value) return fallback;
  if (!value->is_array() || value->size() != length) {
    return source.error(where + ": " + key + " must be an array of " + std::to_string(length) + " numbers");
  }
  std::vector<double> numbers;
  for (const Json& n : *value) {
    if (!n.is_number() || !(std::abs(n.get<double>()) <= std::numeric_limits<float>::max())) {
      return source.error(where + ": " + key + " holds something that is not a finite number");
    }
    numbers.push_back(n.get<double>());
  }
  return numbers;
}

Result<std::vector<uint8_t>> resolveUri(const Source& source, const std::string& uri, const std::string& where) {
  if (uri.rfind("data:", 0) == 0) {
    const size_t comma = uri.find(',');
    if (comma == std::string::npos || uri.substr(0, comma).find(";base64") == std::string::npos) {
      return source.error(where + ": only base64 data: URIs are supported");
    }
    auto bytes = decodeBase64(std::string_view(uri).substr(comma + 1));
    if (!bytes) return source.error(where + ": its data: URI is not valid base64");
    return std::move(*bytes);
  }
  if (uri.find("://") != std::string::npos) return source.error(where + ": cannot fetch " + uri + "; only local files");
  if (source.baseDir.empty()) return source.error(where + ": refers to the file " + uri + ", which is not available here");
  const std::filesystem::path path = source.baseDir / percentDecoded(uri);
  std::vector<std::filesystem::path> folders{source.baseDir};
  folders.insert(folders.end(), source.extraFolders.begin(), source.extraFolders.end());
  if (!insideFolders(path, folders)) {
    // The uri only: nothing of the file refused is read, let alone quoted.
    return source.error(where + ": " + uri + " is outside the model's folder " + source.baseDir.string() +
                        " (photowalk reads a model's files only from its own folder)");
  }
  auto text = readInputFile(path, kBufferInput);
  if (!text) return source.error(where + ": " + text.message());
  return std::vector<uint8_t>(text->begin(), text->end());
}

Result<std::span<const uint8_t>> bufferViewBytes(const Source& source, const Json& index, const std::string& where) {
  auto view = element(source, "bufferViews", index, where);
  if (!view) return view.error();
  const std::string at = where + " (bufferView " + index.dump() + ")";
  const Json* bufferIndex = member(**view, "buffer");
  if (!bufferIndex || !bufferIndex->is_number_unsigned() || bufferIndex->get<size_t>() >= source.buffers.size()) {
    return source.error(at + ": refers to a buffer that does not exist");
  }
  const std::vector<uint8_t>& buffer = source.buffers[bufferIndex->get<size_t>()];
  auto offset = numberOr(source, **view, "byteOffset", 0, at);
  auto length = numberOr(source, **view, "byteLength", -1, at);
  if (!offset) return offset.error();
  if (!length) return length.error();
  if (*offset < 0 || *length < 1 || *offset > static_cast<double>(buffer.size()) ||
      *length > static_cast<double>(buffer.size()) - *offset) {
    return source.error(at + ": does not fit in its buffer of " + std::to_string(buffer.size()) + " bytes");
  }
  return std::span<const uint8_t>(buffer.data() + static_cast<size_t>(*offset), static_cast<size_t>(*length));
}

Result<std::vector<glm::vec4>> readFloatAccessor(const Source& source, const Json& index, int minComponents,
                                                 int maxComponents, bool allowIntegers, const std::string& where) {
  auto layout = accessorLayout(source, index, where);
  if (!layout) return layout.error();
  const AccessorLayout& l = *layout;
  if (l.components < minComponents || l.components > maxComponents) {
    return source.error(where + ": accessor " + index.dump() + " has " + std::to_string(l.components) +
                        " components per element, not " + std::to_string(minComponents) +
                        (maxComponents > minComponents ? " to " + std::to_string(maxComponents) : ""));
  }
  const bool integer = l.componentType != kFloat;
  if (integer && !(allowIntegers && l.normalized)) {
    return source.error(where + ": accessor " + index.dump() + " must hold floats (quantized data needs KHR_mesh_quantization)");
  }
  std::vector<glm::vec4> out(l.count, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  if (!l.data) return out;
  const int bytes = componentBytes(l.componentType);
  for (size_t i = 0; i < l.count; ++i) {
    const uint8_t* p = l.data + i * l.stride;
    for (int c = 0; c < l.components; ++c) {
      const float v = componentValue(p + c * bytes, l.componentType);
      if (!std::isfinite(v)) {
        return source.error(where + ": accessor " + index.dump() + " element " + std::to_string(i) + " is not finite");
      }
      out[i][c] = v;
    }
  }
  return out;
}

Result<std::vector<uint32_t>> readIndexAccessor(const Source& source, const Json& index, size_t vertexCount,
                                                const std::string& where) {
  auto layout = accessorLayout(source, index, where);
  if (!layout) return layout.error();
  const AccessorLayout& l = *layout;
  if (l.components != 1 ||
      (l.componentType != kUnsignedByte && l.componentType != kUnsignedShort && l.componentType != kUnsignedInt)) {
    return source.error(where + ": indices must be unsigned byte, short or int scalars");
  }
  std::vector<uint32_t> out(l.count, 0);
  if (!l.data) return out;
  for (size_t i = 0; i < l.count; ++i) {
    const uint8_t* p = l.data + i * l.stride;
    uint32_t v = 0;
    if (l.componentType == kUnsignedByte) {
      v = p[0];
    } else if (l.componentType == kUnsignedShort) {
      uint16_t s;
      std::memcpy(&s, p, 2);
      v = s;
    } else {
      std::memcpy(&v, p, 4);
    }
    if (v >= vertexCount) {
      return source.error(where + ": index " + std::to_string(i) + " is " + std::to_string(v) + " but there are only " +
                          std::to_string(vertexCount) + " vertices");
    }
    out[i] = v;
  }
  return out;
}

}  // namespace pw::engine::gltf
