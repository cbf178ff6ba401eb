#include "base/atomic_file.h"

#include "base/input_file.h"
#include "base/staging.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>

namespace pw {
namespace fs = std::filesystem;

namespace {

fs::path tempPathFor(const fs::path& path) {
  static thread_local std::mt19937_64 rng{std::random_device{}()};
  std::ostringstream name;
  // Keep the extension last so that writers choosing a format by extension still work.
  // The process id in the name lets a later run remove what a killed one left.
  name << "." << path.stem().string() << ".tmp-" << processIdText() << "-" << std::hex << (rng() & 0xffffff)
       << path.extension().string();
  return path.parent_path() / name.str();
}

}  // namespace

Status writeViaTempFile(const fs::path& path, const std::function<Status(const fs::path&)>& write) {
  std::error_code ec;
  if (path.has_parent_path() && !fs::exists(path.parent_path(), ec)) {
    return makeError(path.string() + ": the folder " + path.parent_path().string() + " does not exist");
  }
  removeStaleTemporaries(path.parent_path(), "." + path.stem().string() + ".tmp-");
  const fs::path temp = tempPathFor(path);
  Status written = write(temp);
  if (written && !fs::exists(temp, ec)) written = makeError(path.string() + ": nothing was written");
  if (!written) {
    fs::remove(temp, ec);
    return written;
  }
  fs::rename(temp, path, ec);
  if (ec) {
    const std::string why = ec.message();  // before the clean-up below overwrites ec
    fs::remove(temp, ec);
    return makeError(path.string() + ": cannot write: " + why);
  }
  return {};
}

Status writeFileAtomic(const fs::path& path, std::span<const char> bytes) {
  return writeViaTempFile(path, [&](const fs::path& temp) -> Status {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out) return makeError(path.string() + ": cannot write: " + std::strerror(errno));
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out) return makeError(path.string() + ": write failed (disk full?)");
    return {};
  });
}

Status writeFileAtomic(const fs::path& path, const std::string& text) {
  return writeFileAtomic(path, std::span<const char>(text.data(), text.size()));
}

Result<std::string> readFile(const fs::path& path) { return readInputFile(path, kAnyInput); }

}  // namespace pw
