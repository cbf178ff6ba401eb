#include "engine/vrml/diagnostics.h"

namespace pw::engine {

namespace {
// A hostile file could produce millions of distinct messages; keep the first ones.
constexpr size_t kMaxDistinctMessages = 1000;
}  // namespace

void Diagnostics::add(Severity severity, std::string message) {
  auto found = index_.find(message);
  if (found != index_.end()) {
    ++items_[found->second].count;
    return;
  }
  if (items_.size() >= kMaxDistinctMessages) {
    if (items_.size() == kMaxDistinctMessages) {
      items_.push_back({Severity::kWarning, "too many distinct warnings; the rest are not listed"});
    }
    ++items_.back().count;
    return;
  }
  index_.emplace(message, items_.size());
  items_.push_back({severity, std::move(message)});
}

int Diagnostics::warningCount() const {
  int n = 0;
  for (const Diagnostic& d : items_) n += d.severity == Severity::kWarning ? 1 : 0;
  return n;
}

std::string Diagnostics::format() const {
  std::string out;
  for (const Diagnostic& d : items_) {
    out += d.severity == Severity::kWarning ? "warning: " : "note: ";
    out += d.message;
    if (d.count > 1) out += " (x" + std::to_string(d.count) + ")";
    out += '\n';
  }
  return out;
}

}  // namespace pw::engine
