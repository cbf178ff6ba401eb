// What each input of a measurement is worth (issue 23): the standard deviation an
// input gets from where it came from, so that the measurement's ± carries the focal
// length, the camera height, the principal point and the lens as well as the corners.
// The assumed focal length's and camera height's are calibrated over the random
// corridors' tune range (docs/accuracy.md, "Calibration of the ±").
#pragma once

#include <string>

#include "metrology/measure.h"
#include "metrology/shot.h"

namespace pw::metrology {

// Where a focal length came from.
enum class FocalOrigin {
  kGiven,            // typed, or on the command line: exact unless its ± is stated
  kExifMm,           // EXIF FocalLength with FocalPlaneXResolution: its rounding
  kExif35mm,         // EXIF FocalLengthIn35mmFilm: rounded to 1 mm, and by the diagonal
  kVanishingPoints,  // from a second finite vanishing point (detect)
  kAssumed,          // nothing known: a 28 mm-equivalent lens
};
const char* focalOriginName(FocalOrigin origin);
// From a shot's focal source (LoadedShot::focalSource, a shot file's focal_source):
// "given"/"shot" -> kGiven, "EXIF FocalLengthIn35mmFilm ..." -> kExif35mm, "EXIF
// FocalLength ..." or "exif" -> kExifMm, "vanishing_points" -> kVanishingPoints,
// "default..."/"assumed..." -> kAssumed.
FocalOrigin focalOriginOf(const std::string& focalSource);

// The assumption a new user gets (the editor's and `measure --assume-defaults`'): the
// focal length of a 28 mm-equivalent lens across the long side (detect.h's
// kDefaultFocalOverLongSide), a standing person's camera height.
inline constexpr double kAssumedFocalOverLongSide = 0.8;
inline constexpr double kAssumedCameraHeightM = 1.6;

// Standard deviations by origin. The assumed ones are calibrated (docs/accuracy.md):
// the random corridors' lenses span 26-50 mm equivalent and their cameras 1.0-1.9 m.
inline constexpr double kAssumedFocalSigmaRelative = 0.32;
// photowalk's focal length from a second finite vanishing point on the York Urban
// photos (48 of the training half's 51 have one): log error mean 0.003, sd 0.220,
// RMS 0.22 (docs/detection-accuracy.md; the median error is 5.1%, the tails are long).
inline constexpr double kVanishingFocalSigmaRelative = 0.22;
inline constexpr double kExif35mmFocalSigmaRelative = 0.03;  // York Urban: 4.1% short
inline constexpr double kExifMmFocalSigmaRelative = 0.01;
inline constexpr double kAssumedCameraHeightSigmaM = 0.28;
// Principal point not given: the photo's centre, within this share of the long side.
inline constexpr double kPrincipalPointSigmaOfLongSide = 0.005;
// Distortion not given (none seen, or estimated from the corners): radial k1 within.
inline constexpr double kUnknownDistortionSigmaK1 = 0.01;

// Two estimates of one focal length (e.g. the EXIF's and a second vanishing point's),
// each with its relative sigma, weighed by inverse variance in log f; the second is
// used only when the two agree within 2 sigma of their difference (else the first
// stands alone: a vanishing point far off is a wrong point, not a noisy one).
struct WeighedFocal {
  double focalPx = 0;
  double sigmaRelative = 0;
  bool usedSecond = false;
};
WeighedFocal weighFocal(double firstPx, double firstSigmaRelative, double secondPx, double secondSigmaRelative);

struct InputOrigins {
  FocalOrigin focal = FocalOrigin::kGiven;
  double givenFocalSigmaRelative = 0;  // the stated ± of a given focal length
  bool cameraHeightAssumed = false;
  double givenCameraHeightSigmaM = 0;  // the stated ± of a given camera height
};

// `options` with every input's standard deviation set for this shot (MeasureOptions'
// focalSigmaRelative, cameraHeightSigmaM, principalPointSigmaPx, distortionSigmaK1 and
// the names said after "mostly:"). A shot that gives its principal point and its
// distortion has them exact.
MeasureOptions withInputSigmas(MeasureOptions options, const Shot& shot, const InputOrigins& origins);

}  // namespace pw::metrology
