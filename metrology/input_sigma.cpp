#include "metrology/input_sigma.h"

#include <algorithm>
#include <cmath>

namespace pw::metrology {

const char* focalOriginName(FocalOrigin origin) {
  switch (origin) {
    case FocalOrigin::kGiven: return "given";
    case FocalOrigin::kExifMm: return "exif_mm";
    case FocalOrigin::kExif35mm: return "exif_35mm";
    case FocalOrigin::kVanishingPoints: return "vanishing_points";
    case FocalOrigin::kAssumed: return "assumed";
  }
  return "?";
}

FocalOrigin focalOriginOf(const std::string& source) {
  const auto starts = [&](const char* prefix) { return source.rfind(prefix, 0) == 0; };
  if (starts("EXIF FocalLengthIn35mmFilm")) return FocalOrigin::kExif35mm;
  if (starts("EXIF") || source == "exif") return FocalOrigin::kExifMm;
  if (source == "vanishing_points" || source.find("vanishing points") != std::string::npos) {
    return FocalOrigin::kVanishingPoints;
  }
  if (starts("default") || starts("assumed")) return FocalOrigin::kAssumed;
  return FocalOrigin::kGiven;
}

WeighedFocal weighFocal(double firstPx, double firstSigma, double secondPx, double secondSigma) {
  WeighedFocal out{firstPx, firstSigma, false};
  if (!(firstPx > 0) || !(secondPx > 0) || !(firstSigma > 0) || !(secondSigma > 0)) return out;
  const double difference = std::log(secondPx / firstPx);
  if (std::abs(difference) > 2.0 * std::hypot(firstSigma, secondSigma)) return out;
  const double w1 = 1.0 / (firstSigma * firstSigma), w2 = 1.0 / (secondSigma * secondSigma);
  out.focalPx = firstPx * std::exp(difference * w2 / (w1 + w2));
  out.sigmaRelative = 1.0 / std::sqrt(w1 + w2);
  out.usedSecond = true;
  return out;
}

MeasureOptions withInputSigmas(MeasureOptions options, const Shot& shot, const InputOrigins& origins) {
  switch (origins.focal) {
    case FocalOrigin::kGiven:
      options.focalSigmaRelative = origins.givenFocalSigmaRelative;
      options.focalSigmaName = "the focal length";
      break;
    case FocalOrigin::kExifMm:
      options.focalSigmaRelative = kExifMmFocalSigmaRelative;
      options.focalSigmaName = "the EXIF focal length's rounding";
      break;
    case FocalOrigin::kExif35mm:
      options.focalSigmaRelative = kExif35mmFocalSigmaRelative;
      options.focalSigmaName = "the EXIF 35 mm-equivalent focal length's rounding";
      break;
    case FocalOrigin::kVanishingPoints:
      options.focalSigmaRelative = kVanishingFocalSigmaRelative;
      options.focalSigmaName = "the focal length from the vanishing points";
      break;
    case FocalOrigin::kAssumed:
      options.focalSigmaRelative = kAssumedFocalSigmaRelative;
      options.focalSigmaName = "the assumed focal length";
      break;
  }
  if (origins.cameraHeightAssumed) {
    options.cameraHeightSigmaM = kAssumedCameraHeightSigmaM;
    options.cameraHeightSigmaName = "the assumed camera height";
  } else {
    options.cameraHeightSigmaM = std::max(options.cameraHeightSigmaM, origins.givenCameraHeightSigmaM);
    options.cameraHeightSigmaName = "the camera height";
  }
  options.principalPointSigmaPx =
      shot.principalPointPx ? 0.0 : kPrincipalPointSigmaOfLongSide * std::max(shot.imageWidth, shot.imageHeight);
  options.distortionSigmaK1 = shot.distortion ? 0.0 : kUnknownDistortionSigmaK1;
  return options;
}

}  // namespace pw::metrology
