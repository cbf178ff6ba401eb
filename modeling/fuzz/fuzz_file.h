// What the file fuzzers share: an input written to a file of this process's own (the
// readers take paths), and the checks every error must pass.
#pragma once

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "base/input_file.h"

namespace pw::fuzz {

// `name` in a folder of this process's own under the system's temporary folder,
// holding `data` (the folder made on first use).
inline std::filesystem::path writeInput(const char* name, const uint8_t* data, size_t size) {
  static const std::filesystem::path folder = [] {
    const std::filesystem::path f = std::filesystem::temp_directory_path() / ("pw-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(f);
    return f;
  }();
  const std::filesystem::path path = folder / name;
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

// An error as the command line prints it must be one line that says something. (A
// library's own error escapes as an exception, which the fuzzer reports as a crash:
// `main` would print it as "internal: ...".)
inline void checkError(std::string_view message) {
  const std::string printed = escapeControls(message);
  const bool bad = printed.empty() || printed.find('\n') != std::string::npos || printed.find('\0') != std::string::npos;
  if (bad) {
    std::fprintf(stderr, "bad error message: %s\n", printed.c_str());
    std::abort();
  }
}

}  // namespace pw::fuzz
