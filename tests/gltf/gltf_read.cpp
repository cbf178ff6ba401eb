// tinygltf's implementation (options in gltf_read.h).
#define TINYGLTF_IMPLEMENTATION
#include "tests/gltf/gltf_read.h"

#include <cstdlib>
#include <cstring>

#include "base/atomic_file.h"
#include "engine/scene/image.h"

namespace pw::engine::testing {

namespace {

bool decodeWithPwScene(tinygltf::Image* image, const int /*index*/, std::string* err, std::string* /*warn*/,
                       int /*reqWidth*/, int /*reqHeight*/, const unsigned char* bytes, int size, void* /*user*/) {
  auto decoded = decodeImage(bytes, static_cast<size_t>(size), "embedded image");
  if (!decoded) {
    if (err) *err += decoded.message();
    return false;
  }
  image->width = decoded->width;
  image->height = decoded->height;
  image->component = 4;
  image->bits = 8;
  image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
  image->image = std::move(decoded->rgba);
  return true;
}

template <class T, int N>
std::vector<T> readFloats(const tinygltf::Model& model, int index) {
  const tinygltf::Accessor& accessor = model.accessors.at(index);
  const tinygltf::BufferView& view = model.bufferViews.at(accessor.bufferView);
  const tinygltf::Buffer& buffer = model.buffers.at(view.buffer);
  if (accessor.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) return {};
  const size_t stride = view.byteStride ? view.byteStride : N * sizeof(float);
  std::vector<T> out(accessor.count);
  for (size_t i = 0; i < accessor.count; ++i) {
    std::memcpy(&out[i], buffer.data.data() + view.byteOffset + accessor.byteOffset + i * stride, N * sizeof(float));
  }
  return out;
}

}  // namespace

Result<tinygltf::Model> parseGltf(const std::vector<uint8_t>& bytes, bool binary) {
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(decodeWithPwScene, nullptr);
  tinygltf::Model model;
  std::string err, warn;
  const bool ok =
      binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), static_cast<unsigned>(bytes.size()))
             : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
                                          static_cast<unsigned>(bytes.size()), "");
  if (!ok || !err.empty()) return makeError("tinygltf: " + err + warn);
  return model;
}

Result<tinygltf::Model> readGltfFile(const std::filesystem::path& path) {
  auto text = readFile(path);
  if (!text) return text.error();
  return parseGltf(std::vector<uint8_t>(text->begin(), text->end()), path.extension() == ".glb");
}

std::vector<glm::vec2> readVec2(const tinygltf::Model& m, int a) { return readFloats<glm::vec2, 2>(m, a); }
std::vector<glm::vec3> readVec3(const tinygltf::Model& m, int a) { return readFloats<glm::vec3, 3>(m, a); }
std::vector<glm::vec4> readVec4(const tinygltf::Model& m, int a) { return readFloats<glm::vec4, 4>(m, a); }

std::vector<uint32_t> readIndices(const tinygltf::Model& model, int index) {
  const tinygltf::Accessor& accessor = model.accessors.at(index);
  const tinygltf::BufferView& view = model.bufferViews.at(accessor.bufferView);
  const uint8_t* data = model.buffers.at(view.buffer).data.data() + view.byteOffset + accessor.byteOffset;
  std::vector<uint32_t> out(accessor.count);
  for (size_t i = 0; i < accessor.count; ++i) {
    if (accessor.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
      uint16_t v;
      std::memcpy(&v, data + 2 * i, 2);
      out[i] = v;
    } else {
      std::memcpy(&out[i], data + 4 * i, 4);
    }
  }
  return out;
}

std::filesystem::path outputDir() {
  // The validator ctest runs the tests again with their files sent to its own folder.
  const char* redirected = std::getenv("PW_GLTF_TEST_OUT");
  const std::filesystem::path dir =
      redirected && *redirected ? std::filesystem::path(redirected) : std::filesystem::path(PW_BINARY_DIR) / "tests" / "gltf" / "out";
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace pw::engine::testing
