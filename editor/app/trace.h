// Traces: what a run did, one row per simulated frame, for tests to read back. The
// shell writes the frame number (and, in JSON lines, the mode's name); the active mode
// adds its own fields (AppMode::traceRow).
//   CSV:        frame,x,y,z,yaw_deg,pitch_deg         (a header from the first row's names)
//               0,0.000000,1.700000,-0.023333,0.0000,0.0000
//   JSON lines: {"frame": 0, "mode": "walk", "x": 0.0, ...}
#pragma once

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/result.h"

namespace pw::app {

enum class TraceFormat { kCsv, kJsonLines };

// One frame's fields, in order.
class TraceRow {
 public:
  // A number; CSV writes it with `decimals` places, JSON as the number it is.
  void add(std::string name, double value, int decimals = 6) {
    fields_.push_back({std::move(name), Number{value, decimals}});
  }
  // Any JSON value (objects, arrays, strings, null): JSON lines only.
  void add(std::string name, nlohmann::ordered_json value) { fields_.push_back({std::move(name), std::move(value)}); }

  struct Number {
    double value;
    int decimals;
  };
  struct Field {
    std::string name;
    std::variant<Number, nlohmann::ordered_json> value;
  };
  const std::vector<Field>& fields() const { return fields_; }

 private:
  std::vector<Field> fields_;
};

class Trace {
 public:
  // Errors: the file cannot be written.
  static Result<std::unique_ptr<Trace>> open(const std::filesystem::path& path, TraceFormat format);

  // Errors: in CSV, a row whose names differ from the header's (a mode with other
  // fields: use JSON lines), or a field that is not a number; the file failing.
  Status write(long frame, std::string_view mode, const TraceRow& row);
  // Writes out what is buffered and closes the file. Errors: the file failing.
  Status close();

 private:
  Trace(std::filesystem::path path, TraceFormat format) : path_(std::move(path)), format_(format) {}
  std::filesystem::path path_;
  TraceFormat format_;
  std::ofstream out_;
  std::vector<std::string> header_;  // CSV, once the first row is written
};

}  // namespace pw::app
