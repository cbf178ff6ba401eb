// Running `photowalk edit` from a test (under xvfb-run) and reading its JSON-lines
// trace back.
#pragma once

#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "tests/support/run_command.h"

namespace pw::edit::test {

inline pw::test::CommandRun photowalk(const std::string& arguments) {
  return pw::test::runCommand(std::string(PW_PHOTOWALK) + " " + arguments);
}

// A replay script (README "The editor's test interface"): lines `FRAME EVENT ARGS`.
class Script {
 public:
  Script& at(int frame, const std::string& event) {
    text_ << frame << ' ' << event << '\n';
    return *this;
  }
  Script& move(int frame, const glm::dvec2& p) {
    std::ostringstream e;
    e.precision(17);
    e << "mousemove " << p.x << ' ' << p.y;
    return at(frame, e.str());
  }
  // Down at `frame`, up `holdFrames` later (ImGui's fields see a key only if it is held
  // across a frame).
  Script& key(int frame, const std::string& name, int holdFrames = 0) {
    return at(frame, "key " + name + " down").at(frame + holdFrames, "key " + name + " up");
  }
  // Ctrl (and Shift) + NAME, all on one frame: the editor's own shortcuts.
  Script& ctrlKey(int frame, const std::string& name, bool shift = false) {
    at(frame, "key LEFT_CONTROL down");
    if (shift) at(frame, "key LEFT_SHIFT down");
    key(frame, name);
    if (shift) at(frame, "key LEFT_SHIFT up");
    return at(frame, "key LEFT_CONTROL up");
  }
  // Ctrl + NAME held across frames (for an ImGui field: Ctrl+A): frames `frame` to `frame + 4`.
  Script& ctrlKeyHeld(int frame, const std::string& name) {
    return at(frame, "key LEFT_CONTROL down").key(frame + 1, name, 2).at(frame + 4, "key LEFT_CONTROL up");
  }
  // Presses at `from` (frame), moves by `by` in `steps` moves one frame apart, releases
  // the frame after: `steps + 2` frames in all.
  Script& drag(int frame, const glm::dvec2& from, const glm::dvec2& by, int steps = 4, const std::string& button = "left") {
    move(frame, from);
    at(frame, "mouse " + button + " down");
    for (int i = 1; i <= steps; ++i) move(frame + i, from + by * (double(i) / steps));
    return at(frame + steps + 1, "mouse " + button + " up");
  }
  // Moves to `p`, presses the frame after and releases the one after that.
  Script& click(int frame, const glm::dvec2& p) {
    return move(frame, p).at(frame + 1, "mouse left down").at(frame + 2, "mouse left up");
  }
  // The same on the centre of a trace's rectangle [x, y, w, h].
  Script& click(int frame, const nlohmann::json& rect) {
    return click(frame, glm::dvec2(double(rect.at(0)) + 0.5 * double(rect.at(2)),
                                   double(rect.at(1)) + 0.5 * double(rect.at(3))));
  }
  std::string str() const { return text_.str(); }

 private:
  std::ostringstream text_;
};

// One row of an editor's --trace.
struct Row {
  long frame = -1;
  std::string mode;
  double scale = 0;
  glm::dvec2 offset{0.0};
  std::vector<glm::dvec2> corners;  // P1..P8; empty when no file is open
  std::optional<std::string> selected;
  std::optional<glm::dvec3> size;  // width, height, length (m)
  std::optional<std::string> path;
  bool dirty = false;
  nlohmann::json raw;
  glm::dvec2 toWindow(const glm::dvec2& photoPx) const { return offset + scale * photoPx; }
};

inline std::vector<Row> readTrace(const std::filesystem::path& path) {
  std::vector<Row> rows;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    Row r;
    r.raw = nlohmann::json::parse(line);
    r.frame = r.raw.at("frame");
    r.mode = r.raw.at("mode");
    if (r.raw.contains("image_to_window")) {
      r.scale = r.raw["image_to_window"].at("scale");
      r.offset = {r.raw["image_to_window"]["offset"][0], r.raw["image_to_window"]["offset"][1]};
    }
    if (r.raw.contains("corners_px") && r.raw["corners_px"].is_object()) {
      for (int k = 1; k <= 8; ++k) {
        const auto& p = r.raw["corners_px"].at("P" + std::to_string(k));
        r.corners.push_back({p[0], p[1]});
      }
    }
    if (r.raw.contains("selected") && r.raw["selected"].is_string()) r.selected = r.raw["selected"];
    if (r.raw.contains("measurement") && r.raw["measurement"].is_object()) {
      const auto& m = r.raw["measurement"];
      r.size = glm::dvec3(m.at("width_m"), m.at("height_m"), m.at("length_m"));
    }
    if (r.raw.contains("document")) {
      if (r.raw["document"]["path"].is_string()) r.path = r.raw["document"]["path"];
      r.dirty = r.raw["document"].at("dirty");
    }
    rows.push_back(std::move(r));
  }
  return rows;
}

}  // namespace pw::edit::test
