#include "modeling/exif.h"

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <memory>

#include <libexif/exif-data.h>
#include <libexif/exif-loader.h>
#include <libexif/exif-log.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "base/input_file.h"
#include "modeling/image_decode.h"

namespace pw::modeling {
namespace {

std::string fixed(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

// libexif's complaints about the block (corrupt data, no memory), the first kept.
struct LogSink {
  std::string firstProblem;
};

void logToSink(ExifLog*, ExifLogCode code, const char* domain, const char* format, va_list args, void* data) {
  if (code != EXIF_LOG_CODE_CORRUPT_DATA && code != EXIF_LOG_CODE_NO_MEMORY) return;
  auto* sink = static_cast<LogSink*>(data);
  if (!sink->firstProblem.empty()) return;
  char text[256];
  std::vsnprintf(text, sizeof text, format, args);
  sink->firstProblem = std::string(domain ? domain : "libexif") + ": " + text;
}

struct ExifDataDeleter {
  void operator()(ExifData* d) const { exif_data_unref(d); }
};
struct ExifLogDeleter {
  void operator()(ExifLog* l) const { exif_log_unref(l); }
};
struct ExifLoaderDeleter {
  void operator()(ExifLoader* l) const { exif_loader_unref(l); }
};

// The entry's first value as a number, when it has the type the tag should have.
std::optional<double> rationalValue(const ExifEntry* e, ExifByteOrder order) {
  if (!e || !e->data || e->components < 1) return std::nullopt;
  if (e->format == EXIF_FORMAT_RATIONAL && e->size >= 8) {
    const ExifRational r = exif_get_rational(e->data, order);
    if (r.denominator == 0) return std::nullopt;
    return double(r.numerator) / double(r.denominator);
  }
  if (e->format == EXIF_FORMAT_SRATIONAL && e->size >= 8) {
    const ExifSRational r = exif_get_srational(e->data, order);
    if (r.denominator == 0) return std::nullopt;
    return double(r.numerator) / double(r.denominator);
  }
  return std::nullopt;
}

std::optional<int> integerValue(const ExifEntry* e, ExifByteOrder order) {
  if (!e || !e->data || e->components < 1) return std::nullopt;
  if (e->format == EXIF_FORMAT_SHORT && e->size >= 2) return int(exif_get_short(e->data, order));
  if (e->format == EXIF_FORMAT_LONG && e->size >= 4) {
    const ExifLong v = exif_get_long(e->data, order);
    return v > 0x7fffffffu ? std::nullopt : std::optional<int>(int(v));
  }
  return std::nullopt;
}

std::string textValue(const ExifEntry* e) {
  if (!e || !e->data || e->format != EXIF_FORMAT_ASCII) return {};
  std::string s(reinterpret_cast<const char*>(e->data), e->size);
  if (const size_t end = s.find('\0'); end != std::string::npos) s.resize(end);
  while (!s.empty() && s.back() == ' ') s.pop_back();
  for (char& c : s) {
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7e) c = '?';
  }
  return s;
}

// An entry of IFD 0 or the EXIF IFD (never the thumbnail's IFD 1).
const ExifEntry* entry(ExifData* data, ExifIfd ifd, ExifTag tag) { return exif_content_get_entry(data->ifd[ifd], tag); }

ExifTags tagsOf(ExifData* data, const LogSink& sink) {
  ExifTags tags;
  const ExifByteOrder order = exif_data_get_byte_order(data);
  tags.make = textValue(entry(data, EXIF_IFD_0, EXIF_TAG_MAKE));
  tags.model = textValue(entry(data, EXIF_IFD_0, EXIF_TAG_MODEL));
  if (auto o = integerValue(entry(data, EXIF_IFD_0, EXIF_TAG_ORIENTATION), order)) {
    if (*o >= 1 && *o <= 8) tags.orientation = *o;
    else tags.notes.push_back("EXIF Orientation " + std::to_string(*o) + " is not one of 1..8: ignored");
  }
  const auto positive = [&](std::optional<double> v, const char* name) -> std::optional<double> {
    if (!v) return std::nullopt;
    if (std::isfinite(*v) && *v > 0) return v;
    tags.notes.push_back(std::string("EXIF ") + name + " " + fixed(*v, 3) + " is not positive: ignored");
    return std::nullopt;
  };
  tags.focalLengthMm = positive(rationalValue(entry(data, EXIF_IFD_EXIF, EXIF_TAG_FOCAL_LENGTH), order), "FocalLength");
  if (auto f35 = integerValue(entry(data, EXIF_IFD_EXIF, EXIF_TAG_FOCAL_LENGTH_IN_35MM_FILM), order); f35 && *f35 > 0) {
    tags.focalLength35mm = double(*f35);  // 0 means unknown (EXIF 2.3)
  }
  tags.focalPlaneXResolution = positive(
      rationalValue(entry(data, EXIF_IFD_EXIF, EXIF_TAG_FOCAL_PLANE_X_RESOLUTION), order), "FocalPlaneXResolution");
  tags.focalPlaneYResolution = positive(
      rationalValue(entry(data, EXIF_IFD_EXIF, EXIF_TAG_FOCAL_PLANE_Y_RESOLUTION), order), "FocalPlaneYResolution");
  if (auto unit = integerValue(entry(data, EXIF_IFD_EXIF, EXIF_TAG_FOCAL_PLANE_RESOLUTION_UNIT), order)) {
    tags.focalPlaneResolutionUnit = *unit;
  }
  const auto dimension = [&](ExifTag tag) -> std::optional<int> {
    auto v = integerValue(entry(data, EXIF_IFD_EXIF, tag), order);
    return (v && *v > 0) ? v : std::nullopt;
  };
  tags.pixelXDimension = dimension(EXIF_TAG_PIXEL_X_DIMENSION);
  tags.pixelYDimension = dimension(EXIF_TAG_PIXEL_Y_DIMENSION);
  tags.present = true;
  if (!sink.firstProblem.empty()) {
    tags.notes.push_back("the photo's EXIF block is corrupt (" + sink.firstProblem + "): what could be read is used");
  }
  return tags;
}

ExifTags load(const unsigned char* bytes, size_t size) {
  ExifTags none;
  if (!bytes || size == 0) return none;
  if (size > 0xffffffu) {  // an APP1 segment holds at most 64 KiB; more is not an EXIF block
    none.notes.push_back("the photo's EXIF block is larger than 16 MiB: ignored");
    return none;
  }
  LogSink sink;
  std::unique_ptr<ExifLog, ExifLogDeleter> log(exif_log_new());
  if (log) exif_log_set_func(log.get(), logToSink, &sink);
  std::unique_ptr<ExifData, ExifDataDeleter> data(exif_data_new());
  if (!data) return none;
  if (log) exif_data_log(data.get(), log.get());
  // As the file is: no "fixing" (libexif would add the spec's mandatory tags with
  // default values, which would read as the camera's).
  exif_data_unset_option(data.get(), EXIF_DATA_OPTION_FOLLOW_SPECIFICATION);
  exif_data_load_data(data.get(), bytes, static_cast<unsigned int>(size));
  ExifTags tags = tagsOf(data.get(), sink);
  bool any = false;
  for (int ifd = 0; ifd < EXIF_IFD_COUNT; ++ifd) any = any || (data->ifd[ifd] && data->ifd[ifd]->count > 0);
  if (!any) {
    ExifTags empty;
    empty.notes.push_back(sink.firstProblem.empty()
                              ? std::string("the photo's EXIF block holds no tags: ignored")
                              : "the photo's EXIF block is corrupt (" + sink.firstProblem + "): ignored");
    return empty;
  }
  return tags;
}

}  // namespace

ExifTags readExifBytes(const uint8_t* data, size_t size) { return load(data, size); }

ExifTags readExif(const std::filesystem::path& path) {
  if (!checkInputFile(path, kPhotoInput)) return {};  // never a FIFO or a device
  std::unique_ptr<ExifLoader, ExifLoaderDeleter> loader(exif_loader_new());
  if (!loader) return {};
  // The loader finds the APP1 "Exif" segment of a JPEG (it reads no further).
  exif_loader_write_file(loader.get(), path.c_str());
  const unsigned char* bytes = nullptr;
  unsigned int size = 0;
  exif_loader_get_buf(loader.get(), &bytes, &size);
  return load(bytes, size);
}

bool orientationSwapsAxes(int orientation) { return orientation >= 5 && orientation <= 8; }

cv::Mat applyOrientation(const cv::Mat& stored, int orientation) {
  // As OpenCV's imread (modules/imgcodecs/src/loadsave.cpp, ApplyExifOrientation).
  cv::Mat out;
  switch (orientation) {
    case 2: cv::flip(stored, out, 1); break;   // mirrored left-right
    case 3: cv::flip(stored, out, -1); break;  // rotated 180
    case 4: cv::flip(stored, out, 0); break;   // mirrored top-bottom
    case 5: cv::transpose(stored, out); break;
    case 6: cv::transpose(stored, out), cv::flip(out, out, 1); break;   // rotated 90 clockwise
    case 7: cv::transpose(stored, out), cv::flip(out, out, -1); break;
    case 8: cv::transpose(stored, out), cv::flip(out, out, 0); break;   // rotated 90 anticlockwise
    default: return stored;
  }
  return out;
}

std::string orientationName(int orientation) {
  switch (orientation) {
    case 2: return "mirrored left to right";
    case 3: return "rotated 180 degrees";
    case 4: return "mirrored top to bottom";
    case 5: return "transposed (mirrored and rotated 90 degrees)";
    case 6: return "rotated 90 degrees clockwise";
    case 7: return "transversed (mirrored and rotated 90 degrees)";
    case 8: return "rotated 90 degrees anticlockwise";
    default: return "";
  }
}

std::optional<ExifFocal> exifFocal(const ExifTags& tags, int storedWidth, int storedHeight,
                                   std::vector<std::string>* notes) {
  const auto note = [&](const std::string& line) {
    if (notes) notes->push_back(line);
  };
  if (!tags.present || storedWidth <= 0 || storedHeight <= 0) return std::nullopt;
  const bool swap = orientationSwapsAxes(tags.orientation);
  const double shownWidth = swap ? storedHeight : storedWidth;
  const double shownHeight = swap ? storedWidth : storedHeight;
  constexpr double kMaxFocalMm = 2000, kMinSensorMm = 0.5, kMaxSensorMm = 200;

  if (tags.focalLengthMm && tags.focalPlaneXResolution) {
    double mmPerUnit = 0;
    const char* unitName = "";
    switch (tags.focalPlaneResolutionUnit) {
      case 2: mmPerUnit = 25.4, unitName = "inch"; break;
      case 3: mmPerUnit = 10.0, unitName = "cm"; break;
      case 4: mmPerUnit = 1.0, unitName = "mm"; break;
      case 5: mmPerUnit = 0.001, unitName = "um"; break;
      default: break;
    }
    const double focalMm = *tags.focalLengthMm;
    if (mmPerUnit == 0) {
      note("EXIF FocalPlaneResolutionUnit " + std::to_string(tags.focalPlaneResolutionUnit) +
           " is not a length: the sensor size is unknown");
    } else {
      // The resolutions count pixels of the image as the camera wrote it (PixelX/Y
      // Dimension), along the stored image's axes.
      const double xPerMm = *tags.focalPlaneXResolution / mmPerUnit;
      const double yPerMm = tags.focalPlaneYResolution.value_or(*tags.focalPlaneXResolution) / mmPerUnit;
      const double sensorXMm = tags.pixelXDimension.value_or(storedWidth) / xPerMm;
      const double sensorYMm = tags.pixelYDimension.value_or(storedHeight) / yPerMm;
      if (focalMm > kMaxFocalMm || sensorXMm < kMinSensorMm || sensorXMm > kMaxSensorMm || sensorYMm < kMinSensorMm ||
          sensorYMm > kMaxSensorMm) {
        note("EXIF FocalLength " + fixed(focalMm, 2) + " mm with a sensor of " + fixed(sensorXMm, 2) + " x " +
             fixed(sensorYMm, 2) + " mm (FocalPlaneXResolution " + fixed(*tags.focalPlaneXResolution, 1) + " px/" +
             unitName + ") is implausible: ignored");
      } else {
        ExifFocal f;
        const double widthMm = swap ? sensorYMm : sensorXMm;
        f.focalMm = metrology::FocalLengthMm{focalMm, widthMm};
        f.sensorHeightMm = swap ? sensorXMm : sensorYMm;
        f.focalPx = f.focalMm->pixels(int(shownWidth));
        f.source = "EXIF FocalLength " + fixed(focalMm, 2) + " mm with FocalPlaneXResolution " +
                   fixed(*tags.focalPlaneXResolution, 1) + " px/" + unitName + " (sensor " + fixed(widthMm, 2) +
                   " x " + fixed(*f.sensorHeightMm, 2) + " mm" + (swap ? ", turned with the photo" : "") + ")";
        return f;
      }
    }
  }
  if (tags.focalLength35mm) {
    const double f35 = *tags.focalLength35mm;
    if (f35 > kMaxFocalMm * 4) {
      note("EXIF FocalLengthIn35mmFilm " + fixed(f35, 0) + " mm is implausible: ignored");
    } else {
      ExifFocal f;
      f.focalPx = f35 / std::hypot(36.0, 24.0) * std::hypot(shownWidth, shownHeight);
      f.source = "EXIF FocalLengthIn35mmFilm " + fixed(f35, 0) + " mm (by the diagonal of a 36 x 24 mm frame)";
      return f;
    }
  }
  if (tags.focalLengthMm) {
    note("EXIF FocalLength " + fixed(*tags.focalLengthMm, 2) +
         " mm, but no sensor size (FocalPlaneXResolution) nor 35 mm equivalent: choose the sensor in the Camera panel");
  }
  return std::nullopt;
}

Result<Photo> readPhoto(const std::filesystem::path& path) {
  Photo photo;
  PW_TRY(checkInputFile(path, kPhotoInput));
  auto decoded = decodeImage(path, cv::IMREAD_COLOR | cv::IMREAD_IGNORE_ORIENTATION);
  if (!decoded) return makeError(path.string() + ": " + decoded.message());
  const cv::Mat& stored = decoded->image;
  photo.exif = readExif(path);
  photo.notes = photo.exif.notes;
  if (decoded->decoderWarning) photo.warnings.push_back(*decoded->decoderWarning);
  photo.focal = exifFocal(photo.exif, stored.cols, stored.rows, &photo.notes);
  photo.bgr = applyOrientation(stored, photo.exif.orientation);
  return photo;
}

}  // namespace pw::modeling
