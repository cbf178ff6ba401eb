// PNG encoding for every writer (textures beside VRML files, glTF embedding, saved
// frames): rows filtered with PNG's Paeth predictor, zlib with the run-length
// strategy, RGB when every pixel is opaque. Several times faster than stb_image_write
// and about a third smaller on photos and rectified textures (bench/gltf_bench.cpp).
#include "engine/scene/image.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>

#include <zlib.h>

namespace pw::engine {

namespace {

void appendUint32(std::vector<uint8_t>& out, uint32_t value) {  // PNG is big-endian
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<uint8_t>(value >> shift));
}

// A chunk: length, type, data, CRC-32 of type and data (PNG spec, 5.3).
void appendChunk(std::vector<uint8_t>& out, const char type[4], const uint8_t* data, size_t size) {
  appendUint32(out, static_cast<uint32_t>(size));
  const size_t typeAt = out.size();
  out.insert(out.end(), type, type + 4);
  if (size > 0) out.insert(out.end(), data, data + size);
  uLong crc = crc32(0L, out.data() + typeAt, 4);
  if (size > 0) crc = crc32(crc, data, static_cast<uInt>(size));  // size < 2^31, checked by the caller
  appendUint32(out, static_cast<uint32_t>(crc));
}

// PNG spec, 9.4: the neighbour closest to left + up - upLeft, ties in that order.
inline int paethPredictor(int left, int up, int upLeft) {
  const int estimate = left + up - upLeft;
  const int toLeft = std::abs(estimate - left), toUp = std::abs(estimate - up), toUpLeft = std::abs(estimate - upLeft);
  if (toLeft <= toUp && toLeft <= toUpLeft) return left;
  return toUp <= toUpLeft ? up : upLeft;
}

bool opaque(const Image& image) {
  for (size_t i = 3; i < image.rgba.size(); i += 4) {
    if (image.rgba[i] != 255) return false;
  }
  return true;
}

}  // namespace

Result<std::vector<uint8_t>> encodePng(const Image& image) {
  if (image.empty()) return makeError("cannot encode an empty image as PNG");
  const size_t width = static_cast<size_t>(image.width), height = static_cast<size_t>(image.height);
  if (image.rgba.size() != width * height * 4) return makeError("image pixel data does not match its size");
  // Grey images (intensity textures) stay grey: PNG colour types 0 and 4 (grey, grey +
  // alpha) from the red channel; colour ones are 2 (RGB) or 6 (RGBA).
  const size_t channels = (image.grey ? 1 : 3) + (opaque(image) ? 0 : 1);
  const size_t rowBytes = width * channels;

  // Each row: filter type byte 4 (Paeth: minus whichever of the left, upper and
  // upper-left bytes best predicts it; PNG spec, 9.4), then the differences. Both the
  // photos (which change little from row to row) and the rectified plane textures
  // (stretched along the corridor, so smooth from column to column) become mostly
  // small numbers in runs, which Z_RLE finds at a fraction of full LZ77's cost. Paeth
  // was the best single filter on both (bench/gltf_bench.cpp); choosing per row as
  // libpng does saved under 2% for about twice the time.
  std::vector<uint8_t> filtered(height * (rowBytes + 1));
  std::vector<uint8_t> previous(rowBytes, 0), current(rowBytes);
  for (size_t y = 0; y < height; ++y) {
    const uint8_t* source = image.rgba.data() + y * width * 4;
    if (channels == 4) {
      std::memcpy(current.data(), source, rowBytes);
    } else if (channels == 3) {
      for (size_t x = 0; x < width; ++x) std::memcpy(&current[3 * x], &source[4 * x], 3);
    } else {
      for (size_t x = 0; x < width; ++x) {
        current[channels * x] = source[4 * x];
        if (channels == 2) current[2 * x + 1] = source[4 * x + 3];
      }
    }
    uint8_t* out = &filtered[y * (rowBytes + 1)];
    out[0] = 4;
    for (size_t i = 0; i < rowBytes; ++i) {
      const int left = i >= channels ? current[i - channels] : 0;
      const int up = previous[i];
      const int upLeft = i >= channels ? previous[i - channels] : 0;
      out[1 + i] = static_cast<uint8_t>(current[i] - paethPredictor(left, up, upLeft));
    }
    std::swap(previous, current);
  }

  if (filtered.size() > std::numeric_limits<uLong>::max() / 2) return makeError("image too large for PNG");
  std::vector<uint8_t> compressed(compressBound(static_cast<uLong>(filtered.size())));
  z_stream stream{};
  if (deflateInit2(&stream, 1, Z_DEFLATED, 15, 8, Z_RLE) != Z_OK) return makeError("zlib: cannot start compression");
  stream.next_in = filtered.data();
  stream.next_out = compressed.data();
  // zlib counts in uInt; feed and drain in pieces for images over 4 GiB of data.
  int status = Z_OK;
  size_t inLeft = filtered.size(), outLeft = compressed.size();
  while (status == Z_OK) {
    const uInt inPiece = static_cast<uInt>(std::min<size_t>(inLeft, std::numeric_limits<uInt>::max()));
    const uInt outPiece = static_cast<uInt>(std::min<size_t>(outLeft, std::numeric_limits<uInt>::max()));
    stream.avail_in = inPiece;
    stream.avail_out = outPiece;
    status = deflate(&stream, inPiece == inLeft ? Z_FINISH : Z_NO_FLUSH);
    inLeft -= inPiece - stream.avail_in;
    outLeft -= outPiece - stream.avail_out;
  }
  const size_t compressedSize = compressed.size() - outLeft;
  deflateEnd(&stream);
  if (status != Z_STREAM_END) return makeError("zlib: compression failed");
  if (compressedSize > 0x7fffffffu) return makeError("image too large for one PNG data chunk");

  std::vector<uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  png.reserve(compressedSize + 64);
  std::vector<uint8_t> header;
  appendUint32(header, static_cast<uint32_t>(width));
  appendUint32(header, static_cast<uint32_t>(height));
  // 8 bits per channel; colour type 0 (grey), 4 (grey + alpha), 2 (RGB) or 6 (RGBA);
  // deflate; adaptive filtering method 0; no interlace (PNG spec, 11.2.2).
  static constexpr uint8_t kColourType[5] = {0, 0, 4, 2, 6};
  header.insert(header.end(), {8, kColourType[channels], 0, 0, 0});
  appendChunk(png, "IHDR", header.data(), header.size());
  appendChunk(png, "IDAT", compressed.data(), compressedSize);
  appendChunk(png, "IEND", nullptr, 0);
  return png;
}

}  // namespace pw::engine
