#include "editor/walk/replay.h"

namespace pw::walk {

std::vector<app::ReplayVerb> replayVerbs() {
  return {{"viewpoint", [](std::istream& words) -> Result<std::any> {
             ViewpointEvent e;
             if (!(words >> e.number) || e.number < 1) {
               return makeError("expected 'viewpoint N' with N = 1, 2, ... (as render --viewpoint)");
             }
             return std::any(e);
           }}};
}

Result<std::vector<app::ReplayEvent>> parseReplay(const std::string& text, const std::string& nameForErrors,
                                                  const std::filesystem::path& baseDir) {
  return app::parseReplay(text, nameForErrors, baseDir, replayVerbs());
}

Result<std::vector<app::ReplayEvent>> readReplay(const std::filesystem::path& path) {
  return app::readReplay(path, replayVerbs());
}

}  // namespace pw::walk
