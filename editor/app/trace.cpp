#include "editor/app/trace.h"

#include <cstdio>

namespace pw::app {

Result<std::unique_ptr<Trace>> Trace::open(const std::filesystem::path& path, TraceFormat format) {
  std::unique_ptr<Trace> trace(new Trace(path, format));
  trace->out_.open(path, std::ios::trunc);
  if (!trace->out_) return makeError(path.string() + ": cannot write the trace");
  return trace;
}

Status Trace::write(long frame, std::string_view mode, const TraceRow& row) {
  if (format_ == TraceFormat::kJsonLines) {
    nlohmann::ordered_json line;
    line["frame"] = frame;
    line["mode"] = mode;
    for (const TraceRow::Field& field : row.fields()) {
      if (const auto* number = std::get_if<TraceRow::Number>(&field.value)) {
        line[field.name] = number->value;
      } else {
        line[field.name] = std::get<nlohmann::ordered_json>(field.value);
      }
    }
    out_ << line.dump() << '\n';
  } else {
    std::vector<std::string> names{"frame"};
    for (const TraceRow::Field& field : row.fields()) names.push_back(field.name);
    if (header_.empty()) {
      header_ = names;
      for (size_t i = 0; i < names.size(); ++i) out_ << (i ? "," : "") << names[i];
      out_ << '\n';
    } else if (names != header_) {
      return makeError(path_.string() + ": mode '" + std::string(mode) +
                       "' traces other columns than the CSV header's (trace to JSON lines instead)");
    }
    std::string line = std::to_string(frame);
    for (const TraceRow::Field& field : row.fields()) {
      const auto* number = std::get_if<TraceRow::Number>(&field.value);
      if (!number) return makeError(path_.string() + ": a CSV trace holds numbers only, not '" + field.name + "'");
      char text[64];
      std::snprintf(text, sizeof text, ",%.*f", number->decimals, number->value);
      line += text;
    }
    out_ << line << '\n';
  }
  if (!out_) return makeError(path_.string() + ": cannot write the trace");
  return {};
}

Status Trace::close() {
  out_.close();
  if (!out_) return makeError(path_.string() + ": cannot write the trace");
  return {};
}

}  // namespace pw::app
