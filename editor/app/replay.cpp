#include "editor/app/replay.h"

#include <algorithm>
#include <optional>
#include <type_traits>
#include <cmath>
#include <sstream>

#include <GLFW/glfw3.h>

#include "base/atomic_file.h"
#include "editor/app/key_names.h"

namespace pw::app {
namespace {

constexpr const char* kShellVerbs = "key, mouse, mousemove, wheel, type, drop, resize, capture, mode, quit, close";

// UTF-8 to code points; nullopt for a malformed sequence.
std::optional<std::vector<unsigned>> codepointsOf(const std::string& text) {
  std::vector<unsigned> out;
  for (size_t i = 0; i < text.size();) {
    const auto byte = static_cast<unsigned char>(text[i]);
    const int extra = byte < 0x80 ? 0 : (byte >> 5) == 0x6 ? 1 : (byte >> 4) == 0xe ? 2 : (byte >> 3) == 0x1e ? 3 : -1;
    if (extra < 0 || i + size_t(extra) >= text.size() + (extra == 0 ? 1 : 0)) return std::nullopt;  // cut short
    unsigned c = extra == 0 ? byte : byte & (0x3fu >> extra);
    for (int k = 1; k <= extra; ++k) {
      const auto next = static_cast<unsigned char>(text[i + k]);
      if ((next >> 6) != 0x2) return std::nullopt;
      c = (c << 6) | (next & 0x3fu);
    }
    out.push_back(c);
    i += extra + 1;
  }
  return out;
}

std::filesystem::path besideScript(const std::string& file, const std::filesystem::path& baseDir) {
  const std::filesystem::path p(file);
  return p.is_relative() ? baseDir / p : p;
}

// One line's event after the frame number, or an error without the file:line.
Result<ReplayAction> parseAction(const std::string& what, std::istream& words, const std::filesystem::path& baseDir,
                                 const std::vector<ReplayVerb>& modeVerbs) {
  if (what == "key") {
    std::string name, state;
    if (!(words >> name >> state) || (state != "down" && state != "up")) return makeError("expected 'key NAME down|up'");
    const int key = keyCodeFromName(name);
    if (key < 0) return makeError("unknown key '" + name + "' (use GLFW names: W, UP, LEFT_SHIFT, PAGE_UP, F12)");
    return ReplayAction(KeyEvent{key, state == "down"});
  }
  if (what == "mouse") {
    std::string first;
    if (!(words >> first)) return makeError("expected 'mouse DX DY' in pixels or 'mouse left|right|middle down|up'");
    static const std::pair<const char*, int> kButtons[] = {
        {"left", GLFW_MOUSE_BUTTON_LEFT}, {"right", GLFW_MOUSE_BUTTON_RIGHT}, {"middle", GLFW_MOUSE_BUTTON_MIDDLE}};
    for (const auto& [name, button] : kButtons) {
      if (first != name) continue;
      std::string state;
      if (!(words >> state) || (state != "down" && state != "up")) {
        return makeError("expected 'mouse " + first + " down|up'");
      }
      return ReplayAction(MouseButtonEvent{button, state == "down"});
    }
    PointerMotionEvent motion;
    std::istringstream number(first);
    if (!(number >> motion.dxPx) || !number.eof() || !(words >> motion.dyPx) || !std::isfinite(motion.dxPx) ||
        !std::isfinite(motion.dyPx)) {
      return makeError("expected 'mouse DX DY' in pixels or 'mouse left|right|middle down|up'");
    }
    return ReplayAction(motion);
  }
  if (what == "mousemove") {
    CursorEvent cursor;
    if (!(words >> cursor.positionPx.x >> cursor.positionPx.y) || !std::isfinite(cursor.positionPx.x) ||
        !std::isfinite(cursor.positionPx.y)) {
      return makeError("expected 'mousemove X Y' in window pixels");
    }
    return ReplayAction(cursor);
  }
  if (what == "wheel") {
    ScrollEvent scroll;
    if (!(words >> scroll.offset.y) || !std::isfinite(scroll.offset.y)) return makeError("expected 'wheel DY' in steps");
    return ReplayAction(scroll);
  }
  if (what == "type") {
    std::string text;
    if (!(words >> text)) return makeError("expected 'type TEXT' (no spaces)");
    auto codepoints = codepointsOf(text);
    if (!codepoints) return makeError("'type': the text is not UTF-8");
    return ReplayAction(TypeRequest{std::move(*codepoints)});
  }
  if (what == "drop") {
    std::string file;
    if (!(words >> file)) return makeError("expected 'drop FILE'");
    return ReplayAction(DropEvent{{besideScript(file, baseDir)}});
  }
  if (what == "resize") {
    ResizeRequest size;
    if (!(words >> size.width >> size.height) || size.width < 1 || size.height < 1 || size.width > 16384 ||
        size.height > 16384) {
      return makeError("expected 'resize WIDTH HEIGHT' in pixels (1..16384)");
    }
    return ReplayAction(size);
  }
  if (what == "capture") {
    std::string file;
    if (!(words >> file)) return makeError("expected 'capture FILE.png'");
    return ReplayAction(CaptureRequest{besideScript(file, baseDir)});
  }
  if (what == "mode") {
    ModeRequest mode;
    if (!(words >> mode.mode)) return makeError("expected 'mode NAME'");
    return ReplayAction(mode);
  }
  if (what == "quit") return ReplayAction(QuitRequest{});
  if (what == "close") return ReplayAction(CloseRequest{});
  for (const ReplayVerb& verb : modeVerbs) {
    if (what != verb.verb) continue;
    auto value = verb.parse(words);
    if (!value) return value.error();
    return ReplayAction(ModeEvent{verb.verb, std::move(*value)});
  }
  std::string known = kShellVerbs;
  for (const ReplayVerb& verb : modeVerbs) known += ", " + verb.verb;
  return makeError("unknown event '" + what + "' (" + known + ")");
}

}  // namespace

std::optional<InputEvent> inputOf(const ReplayAction& action) {
  return std::visit(
      [](const auto& a) -> std::optional<InputEvent> {
        if constexpr (std::is_constructible_v<InputEvent, decltype(a)>) {
          return InputEvent(a);
        } else {
          return std::nullopt;
        }
      },
      action);
}

Result<std::vector<ReplayEvent>> parseReplay(const std::string& text, const std::string& name,
                                             const std::filesystem::path& baseDir,
                                             const std::vector<ReplayVerb>& modeVerbs) {
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
    int frame = 0;
    try {
      size_t used = 0;
      frame = std::stoi(frameText, &used);
      if (used != frameText.size() || frame < 0) throw std::invalid_argument("frame");
    } catch (const std::exception&) {
      return makeError(at + "expected a frame number (0, 1, 2, ...) first, not '" + frameText + "'");
    }
    if (!(words >> what)) {
      std::string known = kShellVerbs;
      for (const ReplayVerb& verb : modeVerbs) known += ", " + verb.verb;
      return makeError(at + "expected an event after the frame (" + known + ")");
    }
    auto action = parseAction(what, words, baseDir, modeVerbs);
    if (!action) return makeError(at + action.message());
    std::string extra;
    if (words >> extra) return makeError(at + "unexpected '" + extra + "' at the end of the line");
    events.push_back({frame, std::move(*action)});
  }
  std::stable_sort(events.begin(), events.end(),
                   [](const ReplayEvent& a, const ReplayEvent& b) { return a.frame < b.frame; });
  return events;
}

Result<std::vector<ReplayEvent>> readReplay(const std::filesystem::path& path, const std::vector<ReplayVerb>& modeVerbs) {
  auto text = readFile(path);
  if (!text) return text.error();
  return parseReplay(*text, path.string(), path.parent_path(), modeVerbs);
}

}  // namespace pw::app
