#include "base/input_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>

namespace pw {
namespace fs = std::filesystem;

std::string formatBytes(std::uintmax_t bytes) {
  if (bytes >= (kMiB << 10) && bytes % (kMiB << 10) == 0) return std::to_string(bytes / (kMiB << 10)) + " GiB";
  if (bytes >= kMiB && bytes % kMiB == 0) return std::to_string(bytes / kMiB) + " MiB";
  if (bytes >= kMiB) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f MiB", static_cast<double>(bytes) / static_cast<double>(kMiB));
    return text;
  }
  return std::to_string(bytes) + " bytes";
}

std::string escapeControls(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if (c >= 0x20 && c != 0x7f) {
      out.push_back(ch);
      continue;
    }
    switch (c) {
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      case '\0': out += "\\0"; break;
      default: {
        char hex[8];
        std::snprintf(hex, sizeof hex, "\\x%02x", c);
        out += hex;
      }
    }
  }
  return out;
}

std::string describeNonRegular(const fs::path& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  switch (status.type()) {
    case fs::file_type::regular: return {};
    case fs::file_type::not_found: {
      std::error_code linkEc;
      return fs::is_symlink(fs::symlink_status(path, linkEc)) ? "a link to nothing" : "no such file";
    }
    case fs::file_type::directory: return "a folder";
    case fs::file_type::fifo: return "a FIFO (named pipe)";
    case fs::file_type::character: return "a character device";
    case fs::file_type::block: return "a block device";
    case fs::file_type::socket: return "a socket";
    case fs::file_type::none:
      return ec ? "unreadable (" + ec.message() + ")" : "unreadable";
    default: return "not a regular file";
  }
}

bool insideFolders(const fs::path& path, const std::vector<fs::path>& folders) {
  std::error_code ec;
  const fs::path resolved = fs::weakly_canonical(fs::absolute(path, ec), ec);
  if (ec) return false;
  for (const fs::path& folder : folders) {
    std::error_code folderEc;
    const fs::path root = fs::weakly_canonical(fs::absolute(folder, folderEc), folderEc);
    if (folderEc || root.empty()) continue;
    // Component by component: /models/a is not inside /models/ab.
    auto r = root.begin(), p = resolved.begin();
    for (; r != root.end() && p != resolved.end() && *r == *p; ++r, ++p) {
    }
    if (r == root.end() || (std::next(r) == root.end() && r->empty())) return true;  // "/models/" ends in ""
  }
  return false;
}

Status checkInputFile(const fs::path& path, const InputKind& kind) {
  const std::string name = escapeControls(path.string());
  const std::string what = describeNonRegular(path);
  if (what == "no such file") return makeError(name + ": no such file");
  if (!what.empty()) {
    return makeError(name + ": is " + what + ", not a file; photowalk reads a " + kind.name + " only from a regular file");
  }
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) return makeError(name + ": cannot read: " + ec.message());
  if (size > kind.maxBytes) {
    return makeError(name + ": the " + std::string(kind.name) + " is " + std::to_string(size) + " bytes, more than the " +
                     formatBytes(kind.maxBytes) + " photowalk reads for a " + kind.name);
  }
  return {};
}

Result<std::string> readInputFile(const fs::path& path, const InputKind& kind) {
  PW_TRY(checkInputFile(path, kind));
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(path, ec);
  std::FILE* file = std::fopen(path.c_str(), "rb");
  const std::string name = escapeControls(path.string());
  if (!file) return makeError(name + ": cannot read: " + std::strerror(errno));
  // One read into a buffer of the file's size (models are tens of MB); then one byte
  // more, to see a file that grew past its size (or its limit) while read.
  std::string bytes(static_cast<size_t>(size), '\0');
  size_t got = std::fread(bytes.data(), 1, bytes.size(), file);
  bool failed = std::ferror(file) != 0;
  char more[4096];
  while (!failed && got == bytes.size()) {
    const size_t extra = std::fread(more, 1, sizeof more, file);
    if (extra == 0) break;
    if (bytes.size() + extra > kind.maxBytes) {
      std::fclose(file);
      return makeError(name + ": the " + std::string(kind.name) + " grew past the " + formatBytes(kind.maxBytes) +
                       " photowalk reads for a " + kind.name + " while it was read");
    }
    bytes.append(more, extra);
    got = bytes.size();
    failed = std::ferror(file) != 0;
  }
  std::fclose(file);
  if (failed) return makeError(name + ": read failed");
  bytes.resize(got);
  return bytes;
}

}  // namespace pw
