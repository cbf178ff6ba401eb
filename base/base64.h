// Base64 (RFC 4648, the standard alphabet, padded): glTF data: URIs, the web page's model.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

namespace pw {

// 4 characters for every 3 bytes or part of 3.
inline size_t base64Size(size_t bytes) { return (bytes + 2) / 3 * 4; }

// Writes base64Size(bytes.size()) characters at `out`.
void base64Into(std::span<const uint8_t> bytes, char* out);

std::string base64(std::span<const uint8_t> bytes);

}  // namespace pw
