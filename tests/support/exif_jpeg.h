// Test photos with EXIF: an EXIF block built with libexif (exif_data_new,
// exif_content_add_entry, exif_data_save_data) and put into a JPEG as an APP1 segment
// right after the SOI marker. No downloaded samples. Link PkgConfig::LIBEXIF.
#pragma once

#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <libexif/exif-data.h>
#include <opencv2/imgcodecs.hpp>

namespace pw::test {

struct ExifFields {
  std::string make, model;
  std::optional<int> orientation;
  std::optional<std::pair<unsigned, unsigned>> focalLength;  // rational mm
  std::optional<int> focalLength35mm;
  std::optional<std::pair<unsigned, unsigned>> focalPlaneXResolution, focalPlaneYResolution;
  std::optional<int> focalPlaneResolutionUnit;
  std::optional<int> pixelXDimension, pixelYDimension;
};

namespace detail {
inline ExifEntry* addEntry(ExifData* data, ExifIfd ifd, ExifTag tag, ExifFormat format, unsigned long components) {
  ExifMem* mem = exif_mem_new_default();
  ExifEntry* e = exif_entry_new_mem(mem);
  const unsigned size = exif_format_get_size(format) * components;
  e->data = static_cast<unsigned char*>(exif_mem_alloc(mem, size));
  e->size = size;
  e->tag = tag;
  e->format = format;
  e->components = components;
  exif_content_add_entry(data->ifd[ifd], e);
  exif_mem_unref(mem);
  exif_entry_unref(e);  // the IFD holds it
  return e;
}
}  // namespace detail

// The EXIF block (starting "Exif\0\0") holding `fields`, little-endian (Intel).
inline std::vector<unsigned char> exifBlock(const ExifFields& f) {
  ExifData* data = exif_data_new();
  exif_data_unset_option(data, EXIF_DATA_OPTION_FOLLOW_SPECIFICATION);
  exif_data_set_byte_order(data, EXIF_BYTE_ORDER_INTEL);
  const ExifByteOrder order = EXIF_BYTE_ORDER_INTEL;
  const auto text = [&](ExifTag tag, const std::string& s) {
    ExifEntry* e = detail::addEntry(data, EXIF_IFD_0, tag, EXIF_FORMAT_ASCII, s.size() + 1);
    std::memcpy(e->data, s.c_str(), s.size() + 1);
  };
  const auto shortTag = [&](ExifIfd ifd, ExifTag tag, int v) {
    exif_set_short(detail::addEntry(data, ifd, tag, EXIF_FORMAT_SHORT, 1)->data, order, ExifShort(v));
  };
  const auto longTag = [&](ExifIfd ifd, ExifTag tag, int v) {
    exif_set_long(detail::addEntry(data, ifd, tag, EXIF_FORMAT_LONG, 1)->data, order, ExifLong(v));
  };
  const auto rational = [&](ExifTag tag, std::pair<unsigned, unsigned> v) {
    exif_set_rational(detail::addEntry(data, EXIF_IFD_EXIF, tag, EXIF_FORMAT_RATIONAL, 1)->data, order,
                      ExifRational{v.first, v.second});
  };
  if (!f.make.empty()) text(EXIF_TAG_MAKE, f.make);
  if (!f.model.empty()) text(EXIF_TAG_MODEL, f.model);
  if (f.orientation) shortTag(EXIF_IFD_0, EXIF_TAG_ORIENTATION, *f.orientation);
  if (f.focalLength) rational(EXIF_TAG_FOCAL_LENGTH, *f.focalLength);
  if (f.focalLength35mm) shortTag(EXIF_IFD_EXIF, EXIF_TAG_FOCAL_LENGTH_IN_35MM_FILM, *f.focalLength35mm);
  if (f.focalPlaneXResolution) rational(EXIF_TAG_FOCAL_PLANE_X_RESOLUTION, *f.focalPlaneXResolution);
  if (f.focalPlaneYResolution) rational(EXIF_TAG_FOCAL_PLANE_Y_RESOLUTION, *f.focalPlaneYResolution);
  if (f.focalPlaneResolutionUnit) shortTag(EXIF_IFD_EXIF, EXIF_TAG_FOCAL_PLANE_RESOLUTION_UNIT, *f.focalPlaneResolutionUnit);
  if (f.pixelXDimension) longTag(EXIF_IFD_EXIF, EXIF_TAG_PIXEL_X_DIMENSION, *f.pixelXDimension);
  if (f.pixelYDimension) longTag(EXIF_IFD_EXIF, EXIF_TAG_PIXEL_Y_DIMENSION, *f.pixelYDimension);
  unsigned char* bytes = nullptr;
  unsigned int size = 0;
  exif_data_save_data(data, &bytes, &size);
  std::vector<unsigned char> block(bytes, bytes + size);
  free(bytes);
  exif_data_unref(data);
  return block;
}

// `image` (BGR) as a JPEG (quality 95) with `app1` (an EXIF block, or any bytes) as an
// APP1 segment right after SOI; none when `app1` is empty. Returns the file's bytes.
inline std::vector<unsigned char> jpegWithApp1(const cv::Mat& image, const std::vector<unsigned char>& app1) {
  std::vector<unsigned char> jpeg;
  cv::imencode(".jpg", image, jpeg, {cv::IMWRITE_JPEG_QUALITY, 95});
  if (app1.empty()) return jpeg;
  const size_t length = app1.size() + 2;  // the segment's length counts its own two bytes
  std::vector<unsigned char> segment = {0xFF, 0xE1, static_cast<unsigned char>(length >> 8),
                                        static_cast<unsigned char>(length & 0xFF)};
  segment.insert(segment.end(), app1.begin(), app1.end());
  jpeg.insert(jpeg.begin() + 2, segment.begin(), segment.end());
  return jpeg;
}

inline void writeBytes(const std::filesystem::path& path, const std::vector<unsigned char>& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

}  // namespace pw::test
