// A photo's camera from its EXIF block (libexif): the focal length in pixels and where
// it came from, and the photo itself with the EXIF orientation applied, so that the
// pixels, the focal length and the sensor's axes agree. No window, no editor: the
// editor and the command-line tools share it.
//
//   auto photo = modeling::readPhoto("IMG_0042.jpg");   // oriented as it is shown
//   if (photo && photo->focal) shot.focalMm = photo->focal->focalMm, shot.focalPx = photo->focal->focalPx;
//
// Tags read: Make (0x010F), Model (0x0110), Orientation (0x0112), FocalLength (0x920A),
// FocalLengthIn35mmFilm (0xA405), FocalPlaneXResolution (0xA20E), FocalPlaneYResolution
// (0xA20F), FocalPlaneResolutionUnit (0xA210), PixelXDimension (0xA002), PixelYDimension
// (0xA003).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "base/result.h"
#include "metrology/shot.h"

namespace pw::modeling {

// The tags as the file holds them, each unset when absent or unusable (a zero
// denominator, a wrong type). Axes are the stored image's (before orientation).
struct ExifTags {
  bool present = false;  // an EXIF block was found
  std::string make, model;
  int orientation = 1;  // 1..8 (TIFF/EXIF); 1 when absent or out of range
  std::optional<double> focalLengthMm;
  std::optional<double> focalLength35mm;
  std::optional<double> focalPlaneXResolution, focalPlaneYResolution;  // pixels per unit
  int focalPlaneResolutionUnit = 2;  // 2 inch (the default), 3 cm, 4 mm, 5 um; 1: none
  std::optional<int> pixelXDimension, pixelYDimension;  // the size the resolutions refer to
  // One line each: what was found wrong and ignored ("the EXIF block is corrupt: ...").
  std::vector<std::string> notes;
};

// Reads the EXIF block of a JPEG file (or raw EXIF bytes starting "Exif\0\0", or a TIFF
// header). Never fails: no block, or a file that cannot be read, gives present = false;
// a corrupt block gives what could be read and a note.
ExifTags readExif(const std::filesystem::path& path);
ExifTags readExifBytes(const uint8_t* data, size_t size);

// True when the orientation turns the image by 90 degrees (5..8): the shown photo's
// width is the stored height, and the sensor's axes swap.
bool orientationSwapsAxes(int orientation);
// The stored pixels turned as the orientation says they are to be shown (as OpenCV's
// imread does without IMREAD_IGNORE_ORIENTATION); 1 or an unknown value: unchanged.
cv::Mat applyOrientation(const cv::Mat& stored, int orientation);
// What the orientation does, in words ("rotated 90 degrees clockwise"); "" for 1.
std::string orientationName(int orientation);

// The camera's focal length for the photo as shown (orientation applied).
struct ExifFocal {
  double focalPx = 0;
  // With FocalLength and FocalPlaneXResolution: the focal length and the sensor's width
  // along the shown photo's width (its height when the orientation turns the photo).
  std::optional<metrology::FocalLengthMm> focalMm;
  std::optional<double> sensorHeightMm;  // along the shown photo's height, with focalMm
  // "EXIF FocalLength 4.20 mm with FocalPlaneXResolution 1000.0 px/cm (sensor 6.40 x 4.80 mm)": the
  // sensor across by down the shown photo (", turned with the photo" when the orientation turned it).
  std::string source;
};

// The focal length in pixels of the shown photo, from the tags of its stored image
// (`storedWidth` x `storedHeight` pixels, before orientation), best first:
// 1. FocalLength with FocalPlaneXResolution (and its unit): the sensor is
//    (PixelXDimension, or the stored width) / resolution wide;
// 2. FocalLengthIn35mmFilm: the 35 mm-equivalent focal length, by the diagonal
//    (f_px = f35 / 43.27 mm x the photo's diagonal in pixels, whatever the orientation).
// None when neither is there (FocalLength alone needs a sensor width: `notes` says so),
// or the values are implausible (a note each).
std::optional<ExifFocal> exifFocal(const ExifTags& tags, int storedWidth, int storedHeight,
                                   std::vector<std::string>* notes = nullptr);

// A photo as it is shown, with its EXIF camera.
struct Photo {
  cv::Mat bgr;  // 8 bit, the orientation applied
  ExifTags exif;
  std::optional<ExifFocal> focal;
  std::vector<std::string> notes;     // the EXIF's notes and exifFocal's
  std::vector<std::string> warnings;  // what the image decoder warned of (image_decode.h)
};

// Reads a PNG or JPEG (BGR, 8 bit), applying the EXIF orientation itself (the pixels
// and the focal length come from the same tags). Errors: a file that is missing or
// not a readable image, or a JPEG cut short (image_decode.h).
Result<Photo> readPhoto(const std::filesystem::path& path);

}  // namespace pw::modeling
