// Running `photowalk edit` from a test (under xvfb-run) and reading its JSON-lines
// trace back.
#pragma once

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "tests/support/run_command.h"

namespace pw::edit::test {

inline pw::test::CommandRun photowalk(const std::string& arguments) {
  return pw::test::runCommand(std::string(PW_PHOTOWALK) + " " + arguments);
}

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
