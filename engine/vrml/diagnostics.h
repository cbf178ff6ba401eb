// Warnings and notes that a reader collects while it still produces a usable scene
// (a missing texture, an unsupported node, a ROUTE that a static scene ignores).
// Errors that stop a load are returned as pw::Error instead.
#pragma once

#include <string>
#include <unordered_map>
#include <vector>

namespace pw::engine {

enum class Severity { kNote, kWarning };

struct Diagnostic {
  Severity severity = Severity::kWarning;
  std::string message;  // "file.wrl:12:5: Text nodes are not supported; skipped"
  int count = 1;        // how many times the identical message was reported
};

// Identical messages are kept once with a count, so that a file with a thousand
// Text nodes gives one line, not a thousand.
class Diagnostics {
 public:
  void warn(std::string message) { add(Severity::kWarning, std::move(message)); }
  void note(std::string message) { add(Severity::kNote, std::move(message)); }

  const std::vector<Diagnostic>& items() const { return items_; }
  int warningCount() const;
  bool empty() const { return items_.empty(); }
  // One line per item: "warning: MESSAGE (x3)".
  std::string format() const;

 private:
  void add(Severity severity, std::string message);

  std::vector<Diagnostic> items_;
  std::unordered_map<std::string, size_t> index_;
};

}  // namespace pw::engine
