#include "editor/walk/replay.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <unordered_map>

#include "base/atomic_file.h"

namespace pw::walk {

int keyCodeFromName(const std::string& name) {
  // GLFW 3.3 key codes (GLFW/glfw3.h).
  static const std::unordered_map<std::string, int> kKeys = [] {
    std::unordered_map<std::string, int> keys{
        {"SPACE", 32},       {"ESCAPE", 256},     {"ENTER", 257},     {"TAB", 258},         {"BACKSPACE", 259},
        {"RIGHT", 262},      {"LEFT", 263},       {"DOWN", 264},      {"UP", 265},          {"PAGE_UP", 266},
        {"PAGE_DOWN", 267},  {"HOME", 268},       {"END", 269},       {"LEFT_SHIFT", 340},  {"LEFT_CONTROL", 341},
        {"LEFT_ALT", 342},   {"RIGHT_SHIFT", 344}, {"RIGHT_CONTROL", 345}, {"RIGHT_ALT", 346}};
    for (char c = 'A'; c <= 'Z'; ++c) keys[std::string(1, c)] = c;
    for (char c = '0'; c <= '9'; ++c) keys[std::string(1, c)] = c;
    for (int f = 1; f <= 25; ++f) keys["F" + std::to_string(f)] = 289 + f;
    return keys;
  }();
  auto it = kKeys.find(name);
  return it == kKeys.end() ? -1 : it->second;
}

Result<std::vector<ReplayEvent>> parseReplay(const std::string& text, const std::string& name,
                                             const std::filesystem::path& baseDir) {
  std::vector<ReplayEvent> events;
  std::istringstream lines(text);
  std::string line;
  int lineNumber = 0;
  while (std::getline(lines, line)) {
    ++lineNumber;
    const std::string at = name + ":" + std::to_string(lineNumber) + ": ";
    if (auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    std::string frameText, what;
    if (!(words >> frameText)) continue;  // blank
    ReplayEvent e;
    try {
      size_t used = 0;
      e.frame = std::stoi(frameText, &used);
      if (used != frameText.size() || e.frame < 0) throw std::invalid_argument("frame");
    } catch (const std::exception&) {
      return makeError(at + "expected a frame number (0, 1, 2, ...) first, not '" + frameText + "'");
    }
    if (!(words >> what)) return makeError(at + "expected key, mouse, viewpoint, resize, capture or quit after the frame");
    if (what == "key") {
      std::string state;
      e.kind = ReplayEvent::Kind::kKey;
      if (!(words >> e.name >> state) || (state != "down" && state != "up")) {
        return makeError(at + "expected 'key NAME down|up'");
      }
      if (keyCodeFromName(e.name) < 0) return makeError(at + "unknown key '" + e.name + "' (use GLFW names: W, UP, LEFT_SHIFT, PAGE_UP, F12)");
      e.down = state == "down";
    } else if (what == "mouse") {
      e.kind = ReplayEvent::Kind::kMouse;
      if (!(words >> e.dx >> e.dy) || !std::isfinite(e.dx) || !std::isfinite(e.dy)) return makeError(at + "expected 'mouse DX DY' in pixels");
    } else if (what == "viewpoint") {
      e.kind = ReplayEvent::Kind::kViewpoint;
      if (!(words >> e.index) || e.index < 1) return makeError(at + "expected 'viewpoint N' with N = 1, 2, ... (as render --viewpoint)");
    } else if (what == "resize") {
      e.kind = ReplayEvent::Kind::kResize;
      if (!(words >> e.dx >> e.dy) || e.dx < 1 || e.dy < 1 || e.dx > 16384 || e.dy > 16384) {
        return makeError(at + "expected 'resize WIDTH HEIGHT' in pixels (1..16384)");
      }
    } else if (what == "capture") {
      e.kind = ReplayEvent::Kind::kCapture;
      std::string file;
      if (!(words >> file)) return makeError(at + "expected 'capture FILE.png'");
      std::filesystem::path p(file);
      e.name = (p.is_relative() ? baseDir / p : p).string();
    } else if (what == "quit") {
      e.kind = ReplayEvent::Kind::kQuit;
    } else {
      return makeError(at + "unknown event '" + what + "' (key, mouse, viewpoint, resize, capture, quit)");
    }
    std::string extra;
    if (words >> extra) return makeError(at + "unexpected '" + extra + "' at the end of the line");
    events.push_back(e);
  }
  std::stable_sort(events.begin(), events.end(), [](const ReplayEvent& a, const ReplayEvent& b) { return a.frame < b.frame; });
  return events;
}

Result<std::vector<ReplayEvent>> readReplay(const std::filesystem::path& path) {
  auto text = readFile(path);
  if (!text) return text.error();
  return parseReplay(*text, path.string(), path.parent_path());
}

}  // namespace pw::walk
