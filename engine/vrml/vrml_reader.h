// Reading VRML97 (ISO/IEC 14772-1:1997, classic UTF-8 encoding) into the scene model.
//
// Plain or gzip-compressed files (detected by content, whatever the name). Syntax
// errors, a USE of an undefined name, a field of the wrong type, unbalanced brackets,
// unterminated strings and truncated or corrupt gzip data fail the read with one line:
// "file.wrl:12:5: expected ... , found ...". What still leaves a usable scene (a
// missing texture, an unknown node, a ROUTE, an Inline that cannot be read) is a
// warning or note in `diagnostics`, which may be null.
#pragma once

#include <filesystem>
#include <string_view>
#include <vector>

#include "base/result.h"
#include "engine/scene/scene.h"
#include "engine/vrml/diagnostics.h"

namespace pw::engine {

// Decompressed input larger than this is refused (about four times as much memory is
// needed to hold its nodes).
inline constexpr size_t kMaxVrmlBytes = size_t{1} << 30;

// Its Inlines, textures and EXTERNPROTOs are read only from inside the model's folder
// and `extraFolders` (README: What photowalk reads); others are skipped with a warning.
Result<Scene> readVrml(const std::filesystem::path& path, Diagnostics* diagnostics,
                       const std::vector<std::filesystem::path>& extraFolders = {});

// The same for text in memory (which may be gzip data). Relative urls resolve against
// `baseDir` (and stay inside it); `nameForMessages` stands for the file name in errors.
Result<Scene> readVrmlString(std::string_view text, const std::filesystem::path& baseDir, Diagnostics* diagnostics,
                             std::string_view nameForMessages = "<string>",
                             const std::vector<std::filesystem::path>& extraFolders = {});

}  // namespace pw::engine
