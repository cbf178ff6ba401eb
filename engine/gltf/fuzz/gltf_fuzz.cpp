// libFuzzer target for the glTF reader (and, on what it accepts, the writer).
//
//   cmake --preset fuzz && cmake --build --preset fuzz --target gltf_fuzz
//   build-fuzz/fuzz/gltf_fuzz -max_len=65536 CORPUS_DIR engine/gltf/fuzz/corpus
//
// Any input must give a scene or an error, never a crash, a hang or a leak. A scene
// that was read must also be writable, and the written file must read back with the
// same number of shapes.
#include <cstdint>
#include <cstdlib>
#include <span>

#include "engine/gltf/gltf_reader.h"
#include "engine/gltf/gltf_writer.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  // No base folder: URIs naming files are refused, so no file system access.
  auto scene = pw::engine::parseGltf(std::span<const uint8_t>(data, size), {}, "fuzz.glb");
  if (!scene.ok()) return 0;
  auto written = pw::engine::encodeGltf(*scene, pw::engine::GltfContainer::kGlb);
  if (!written.ok()) std::abort();
  auto back = pw::engine::parseGltf(*written, {}, "rewritten.glb");
  if (!back.ok() || back->shapes.size() != scene->shapes.size()) std::abort();
  return 0;
}
