#include "engine/vrml/gzip.h"

#include <algorithm>
#include <climits>

#include <zlib.h>

namespace pw::engine {

bool isGzip(std::string_view bytes) {
  return bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == 0x1f && static_cast<unsigned char>(bytes[1]) == 0x8b;
}

Result<std::string> gunzip(std::string_view bytes, const std::string& name, size_t maxBytes) {
  std::string out;
  z_stream z{};
  if (inflateInit2(&z, 16 + MAX_WBITS) != Z_OK) return makeError(name + ": zlib initialisation failed");
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  size_t inputLeft = bytes.size();
  char buffer[1 << 16];
  int rc = Z_OK;
  while (true) {
    if (z.avail_in == 0 && inputLeft > 0) {
      const size_t chunk = std::min<size_t>(inputLeft, UINT_MAX);
      z.avail_in = static_cast<uInt>(chunk);
      inputLeft -= chunk;
    }
    z.next_out = reinterpret_cast<Bytef*>(buffer);
    z.avail_out = sizeof buffer;
    rc = inflate(&z, Z_NO_FLUSH);
    const size_t produced = sizeof buffer - z.avail_out;
    if (out.size() + produced > maxBytes) {
      inflateEnd(&z);
      return makeError(name + ": decompresses to more than " + std::to_string(maxBytes >> 20) +
                       " MiB; photowalk refuses it");
    }
    out.append(buffer, produced);
    if (rc == Z_STREAM_END) {
      // Another gzip member may follow (as `cat a.gz b.gz` makes).
      if (z.avail_in >= 2 && static_cast<unsigned char>(z.next_in[0]) == 0x1f &&
          static_cast<unsigned char>(z.next_in[1]) == 0x8b) {
        inflateReset(&z);
        continue;
      }
      break;
    }
    if (rc == Z_NEED_DICT || rc == Z_DATA_ERROR || rc == Z_MEM_ERROR || rc == Z_STREAM_ERROR) {
      const std::string why = z.msg ? z.msg : "invalid data";
      inflateEnd(&z);
      return makeError(name + ": corrupt gzip data (" + why + ")");
    }
    if (rc == Z_BUF_ERROR || (z.avail_in == 0 && inputLeft == 0 && produced == 0)) {
      inflateEnd(&z);
      return makeError(name + ": the gzip stream is truncated (the file ends before the compressed data does)");
    }
  }
  inflateEnd(&z);
  return out;
}

Result<std::string> gzipCompress(std::string_view text) {
  z_stream z{};
  if (deflateInit2(&z, 4, Z_DEFLATED, 16 + MAX_WBITS, 8, Z_DEFAULT_STRATEGY) != Z_OK) {
    return makeError("zlib initialisation failed");
  }
  std::string out;
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(text.data()));
  size_t inputLeft = text.size();
  char buffer[1 << 16];
  int rc = Z_OK;
  do {
    if (z.avail_in == 0 && inputLeft > 0) {
      const size_t chunk = std::min<size_t>(inputLeft, UINT_MAX);
      z.avail_in = static_cast<uInt>(chunk);
      inputLeft -= chunk;
    }
    z.next_out = reinterpret_cast<Bytef*>(buffer);
    z.avail_out = sizeof buffer;
    rc = deflate(&z, inputLeft == 0 ? Z_FINISH : Z_NO_FLUSH);
    if (rc == Z_STREAM_ERROR) {
      deflateEnd(&z);
      return makeError("gzip compression failed");
    }
    out.append(buffer, sizeof buffer - z.avail_out);
  } while (rc != Z_STREAM_END);
  deflateEnd(&z);
  return out;
}

}  // namespace pw::engine
