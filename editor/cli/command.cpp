#include "editor/cli/command.h"

#include "base/input_file.h"

#include <cctype>
#include <charconv>
#include <filesystem>
#include <cmath>
#include <cstdio>

namespace pw::editor {

namespace {
std::vector<Command>& registry() {
  static std::vector<Command> all;
  return all;
}

bool matches(const std::string& arg, std::string_view name, std::string_view alias) {
  return arg == name || (!alias.empty() && arg == alias);
}
}  // namespace

const std::vector<Command>& commands() { return registry(); }

CommandRegistrar::CommandRegistrar(const Command& command) { registry().push_back(command); }

namespace {
void printLine(const char* prefix, std::string_view message) {
  const std::string line = escapeControls(message);
  std::fprintf(stderr, "%s: %s\n", prefix, line.c_str());
}
}  // namespace

int fail(std::string_view message) {
  printLine("error", message);
  return kExitFailure;
}

Status checkNotAnInput(const std::string& output, std::string_view option, const std::vector<NamedInput>& inputs) {
  std::error_code ec;
  if (!std::filesystem::exists(output, ec)) return {};
  for (const NamedInput& input : inputs) {
    if (input.path.empty()) continue;
    std::error_code same;
    if (!std::filesystem::equivalent(output, input.path, same) || same) continue;
    return makeError(std::string(option) + " " + output + " is " + input.what + " (" + input.path +
                     "), which the command reads; photowalk never writes over its input: choose another name");
  }
  return {};
}

Status checkImageExtension(const std::string& path, std::string_view option) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".png" || ext == ".jpg" || ext == ".jpeg") return {};
  return makeError(std::string(option) + " " + path + ": an image's name ends in .png, .jpg or .jpeg" +
                   (ext.empty() ? std::string() : ", not " + ext));
}

void printWarning(std::string_view message) { printLine("warning", message); }
void printNote(std::string_view message) { printLine("note", message); }

bool Args::flag(std::string_view name, std::string_view alias) {
  bool found = false;
  for (size_t i = 0; i < args_.size(); ++i) {
    if (!used_[i] && matches(args_[i], name, alias)) used_[i] = found = true;
  }
  return found;
}

std::vector<std::string> Args::values(std::string_view name, std::string_view alias) {
  std::vector<std::string> out;
  for (size_t i = 0; i < args_.size(); ++i) {
    if (used_[i]) continue;
    const std::string& a = args_[i];
    if (matches(a, name, alias)) {
      used_[i] = true;
      if (i + 1 >= args_.size()) {
        if (error_.empty()) error_ = std::string(name) + " needs a value";
      } else {
        used_[++i] = true;
        out.push_back(args_[i]);
      }
    } else if (a.size() > name.size() && a.compare(0, name.size(), name) == 0 && a[name.size()] == '=') {
      used_[i] = true;
      out.push_back(a.substr(name.size() + 1));
    }
  }
  return out;
}

std::optional<std::string> Args::value(std::string_view name, std::string_view alias) {
  auto all = values(name, alias);
  if (all.empty()) return std::nullopt;
  if (all.size() > 1 && error_.empty()) error_ = std::string(name) + " is given more than once";
  return all.back();
}

std::vector<std::string> Args::positionals() {
  std::vector<std::string> out;
  for (size_t i = 0; i < args_.size(); ++i) {
    const std::string& a = args_[i];
    if (used_[i] || (a.size() > 1 && a[0] == '-')) continue;
    used_[i] = true;
    out.push_back(a);
  }
  return out;
}

Status Args::finish() const {
  if (!error_.empty()) return makeError(error_);
  for (size_t i = 0; i < args_.size(); ++i) {
    if (!used_[i]) return makeError("unknown option " + args_[i]);
  }
  return {};
}

Result<std::pair<int, int>> parseSize(std::string_view text, std::string_view optionName) {
  const auto bad = [&] {
    return makeError(std::string(optionName) + " wants WIDTHxHEIGHT in pixels, e.g. 1280x720, not '" + std::string(text) + "'");
  };
  const size_t x = text.find('x');
  if (x == std::string_view::npos) return bad();
  int w = 0, h = 0;
  auto r1 = std::from_chars(text.data(), text.data() + x, w);
  auto r2 = std::from_chars(text.data() + x + 1, text.data() + text.size(), h);
  if (r1.ec != std::errc() || r1.ptr != text.data() + x || r2.ec != std::errc() || r2.ptr != text.data() + text.size()) {
    return bad();
  }
  constexpr int kMaxSide = 16384;
  if (w <= 0 || h <= 0 || w > kMaxSide || h > kMaxSide) {
    return makeError(std::string(optionName) + " " + std::string(text) + " is out of range: each side must be 1.." +
                     std::to_string(kMaxSide) + " pixels");
  }
  return std::pair{w, h};
}

Result<double> parseNumber(std::string_view text, std::string_view optionName) {
  double v = 0;
  auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  if (r.ec != std::errc() || r.ptr != text.data() + text.size() || !std::isfinite(v)) {
    return makeError(std::string(optionName) + " wants a number, not '" + std::string(text) + "'");
  }
  return v;
}

Result<int> parsePositiveInt(std::string_view text, std::string_view optionName) {
  int value = 0;
  auto r = std::from_chars(text.data(), text.data() + text.size(), value);
  if (r.ec != std::errc() || r.ptr != text.data() + text.size() || value < 1) {
    return makeError(std::string(optionName) + " wants a whole number from 1, not '" + std::string(text) + "'");
  }
  return value;
}

}  // namespace pw::editor
