// Atomic file output: a failed run never leaves a half-written file behind.
#pragma once

#include <filesystem>
#include <functional>
#include <span>
#include <string>

#include "base/result.h"

namespace pw {

// Writes `bytes` to `path` through a temporary file in the same directory that is
// renamed over `path` only once everything was written and flushed.
Status writeFileAtomic(const std::filesystem::path& path, std::span<const char> bytes);
Status writeFileAtomic(const std::filesystem::path& path, const std::string& text);

// Calls `write(tempPath)` to produce the file under a temporary name beside `path`,
// then renames it into place. If `write` fails or leaves no file, the temporary is
// removed and `path` is untouched. Use this for writers that want a file name
// (cv::imwrite, stbi_write_png, a library's save function).
Status writeViaTempFile(const std::filesystem::path& path,
                        const std::function<Status(const std::filesystem::path& tempPath)>& write);

// Reads a whole file; the error names the file and the reason.
Result<std::string> readFile(const std::filesystem::path& path);

}  // namespace pw
