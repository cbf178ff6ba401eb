// Writes every sample scene as OUT_DIR/NAME.glb and OUT_DIR/NAME.gltf, for the
// Khronos glTF validator ctest (tests/gltf/validate.sh).
#include <cstdio>
#include <filesystem>

#include "engine/gltf/gltf_writer.h"
#include "tests/gltf/sample_scenes.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: gltf_write_samples OUT_DIR\n");
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  int failures = 0;
  for (const auto& sample : pw::engine::samples::allSamples()) {
    const pw::engine::Scene scene = sample.make();
    for (const char* extension : {".glb", ".gltf"}) {
      const auto path = dir / (sample.name + extension);
      const pw::Status status = pw::engine::writeGltf(scene, path);
      if (!status) {
        std::fprintf(stderr, "error: %s\n", status.message().c_str());
        ++failures;
      }
    }
  }
  return failures == 0 ? 0 : 1;
}
