// libFuzzer target for the VRML97 reader (and, on what it accepts, the writer).
//
//   cmake --preset fuzz && cmake --build --preset fuzz --target vrml_fuzz
//   build-fuzz/fuzz/vrml_fuzz -dict=engine/vrml/fuzz/vrml.dict -max_len=65536 CORPUS_DIR engine/vrml/fuzz/corpus
//
// Any input must give a scene or an error, never a crash, a hang or a leak. A scene
// that was read must also be writable, and the written text must read back with the
// same number of shapes.
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "engine/vrml/vrml_reader.h"
#include "engine/vrml/vrml_writer.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  pw::engine::Diagnostics diagnostics;
  // Urls resolve into a folder that does not exist: no file system access.
  auto scene = pw::engine::readVrmlString(text, "/nonexistent-photowalk-fuzz", &diagnostics, "fuzz.wrl");
  if (!scene.ok()) return 0;
  auto written = pw::engine::vrmlText(*scene, {}, {});
  if (!written.ok()) std::abort();
  auto back = pw::engine::readVrmlString(*written, "/nonexistent-photowalk-fuzz", nullptr, "rewritten.wrl");
  if (!back.ok() || back->shapes.size() != scene->shapes.size()) std::abort();
  return 0;
}
