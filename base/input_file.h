// Reading input files: the one place photowalk opens a file it did not write.
//
// Only regular files are read (a FIFO would block for ever, /dev/zero would be read
// until memory runs out), and never more than the limit of the file's kind: each
// read states what it reads (a photo, a model, a texture, a buffer...). Libraries
// that open a file by name themselves (OpenCV's imread, libexif) get the same check
// first through checkInputFile.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "base/result.h"

namespace pw {

// What is read, for the messages, and the most bytes photowalk reads of it.
struct InputKind {
  const char* name;
  std::uintmax_t maxBytes;
};

inline constexpr std::uintmax_t kMiB = std::uintmax_t{1} << 20;
inline constexpr InputKind kPhotoInput{"photo", 512 * kMiB};
inline constexpr InputKind kModelInput{"model", 1024 * kMiB};  // VRML (also gunzipped), glTF, GLB
inline constexpr InputKind kTextureInput{"texture", 256 * kMiB};
inline constexpr InputKind kBufferInput{"buffer", 1024 * kMiB};  // a glTF's .bin
inline constexpr InputKind kShotInput{"shot", 16 * kMiB};
inline constexpr InputKind kLayoutInput{"layout", 16 * kMiB};
inline constexpr InputKind kFontInput{"font", 64 * kMiB};
inline constexpr InputKind kTextInput{"file", 64 * kMiB};  // editor documents, replay scripts
inline constexpr InputKind kAnyInput{"file", 1024 * kMiB};  // readFile() without a kind

// "a FIFO (named pipe)", "a character device", "a folder"... for what is at `path`
// (following links); empty for a regular file.
std::string describeNonRegular(const std::filesystem::path& path);

// OK when `path` is a regular file (through links) of at most kind.maxBytes; else an
// error naming the path and what it is ("is a FIFO (named pipe), not a file").
Status checkInputFile(const std::filesystem::path& path, const InputKind& kind);

// The whole file after checkInputFile; a file that grows past the limit while read
// is refused too.
Result<std::string> readInputFile(const std::filesystem::path& path, const InputKind& kind);

// True when `path`, its links and `..` resolved (as far as it exists), lies inside
// one of `folders` (themselves resolved): where a model from someone else may read
// (its Inlines, textures, buffers). An empty list allows nothing.
bool insideFolders(const std::filesystem::path& path, const std::vector<std::filesystem::path>& folders);

// "12 MiB", "1 GiB", "700 bytes": a limit as the messages and README state it.
std::string formatBytes(std::uintmax_t bytes);

// `text` with control characters (and DEL) written as \n, \t, \r, \0 or \xNN, and
// backslashes left as they are: what a one-line message may quote.
std::string escapeControls(std::string_view text);

}  // namespace pw
