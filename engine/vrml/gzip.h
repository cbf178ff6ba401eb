// gzip streams for .wrl.gz (and gzip-compressed files named .wrl), through zlib.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "base/result.h"

namespace pw::engine {

// True when the bytes start with the gzip magic number (RFC 1952: 1f 8b).
bool isGzip(std::string_view bytes);

// Inflates a gzip stream (several concatenated members allowed). A truncated or
// corrupt stream, or one that would inflate beyond `maxBytes`, is an error naming
// `nameForErrors`.
Result<std::string> gunzip(std::string_view bytes, const std::string& nameForErrors, size_t maxBytes);

// Deflates `text` into a gzip stream at zlib level 4: on the 80 MB mesh of
// bench/vrml_bench.cpp it is 3% larger than level 6 and 9 in a quarter of level 6's
// time (level 9 took 24 s); VRML's repetitive number text makes the higher levels'
// long match searches expensive.
Result<std::string> gzipCompress(std::string_view text);

}  // namespace pw::engine
