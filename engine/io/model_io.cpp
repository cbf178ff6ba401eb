#include "engine/io/model_io.h"

#include <system_error>

#include "base/input_file.h"
#include "engine/scene/sample_scene.h"
#include "engine/gltf/gltf_reader.h"
#include "engine/vrml/vrml_reader.h"

namespace pw::engine {

Result<engine::Scene> loadModel(const std::filesystem::path& path, std::vector<std::string>* warnings,
                                const std::vector<std::filesystem::path>& extraFolders) {
  if (path == kSampleSceneName) return engine::makeSampleScene();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    return makeError(path.string() + ": no such file (or use '" + kSampleSceneName + "' for the built-in room)");
  }
  PW_TRY(checkInputFile(path, kModelInput));  // no FIFO, no device, nothing too large
  const std::string ext = path.extension().string();
  std::string name = path.filename().string();
  for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (name.ends_with(".wrl") || name.ends_with(".wrl.gz") || name.ends_with(".wrz") || name.ends_with(".vrml")) {
    engine::Diagnostics diagnostics;
    auto scene = engine::readVrml(path, &diagnostics, extraFolders);
    if (warnings) {
      for (const engine::Diagnostic& d : diagnostics.items()) {
        warnings->push_back((d.severity == engine::Severity::kNote ? "note: " : "") + d.message +
                            (d.count > 1 ? " (x" + std::to_string(d.count) + ")" : ""));
      }
    }
    return scene;
  }
  if (name.ends_with(".glb") || name.ends_with(".gltf")) return engine::readGltf(path, warnings, extraFolders);
  return makeError(path.string() + ": cannot read " + (ext.empty() ? "files without an extension" : ext + " files") +
                   ": photowalk reads VRML97 (.wrl, .wrl.gz) and glTF 2.0 (.glb, .gltf)");
}

}  // namespace pw::engine
