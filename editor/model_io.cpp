#include "editor/model_io.h"

#include <system_error>

#include "engine/scene/sample_scene.h"

namespace pw::editor {

Result<engine::Scene> loadModel(const std::filesystem::path& path, std::vector<std::string>* warnings) {
  (void)warnings;  // nothing produces warnings until the VRML reader is hooked in here
  if (path == kSampleSceneName) return engine::makeSampleScene();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    return makeError(path.string() + ": no such file (or use '" + kSampleSceneName + "' for the built-in room)");
  }
  const std::string ext = path.extension().string();
  return makeError(path.string() + ": cannot read " + (ext.empty() ? "files without an extension" : ext + " files") +
                   " yet; the only scene available is the built-in '" + kSampleSceneName + "'");
}

}  // namespace pw::editor
