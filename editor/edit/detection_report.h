// The "detection" object of a shot file: what automatic detection found (`photowalk
// detect` writes it, and so does the editor for a photo it opens alone), read back by the
// editor so that a box detection was unsure of opens as the suggestion it is, with its
// doubts and each corner's confidence, for as long as its corners are where detection
// put them (README "Shot files").
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "metrology/shot.h"
#include "metrology/detect/detect.h"

namespace pw::edit {

// The report of `d`. `lensGiven`: the photo was read through a lens given, not fitted
// (DetectOptions::lens); `focalFromExif`: the focal length given was the photo's EXIF's.
nlohmann::json detectionReport(const metrology::detect::CorridorDetection& d, bool lensGiven, bool focalFromExif);

// A report as read back: where detection put each corner and how sure it was of it.
struct DetectionReport {
  bool confident = false;
  std::vector<std::string> doubts;
  std::array<glm::dvec2, metrology::kCornerCount> px{};
  std::array<double, metrology::kCornerCount> confidence{};
};

// The report in a shot file's fields (its "detection" object), where it found a box and
// gives every corner's px and confidence; nullopt otherwise (no report, one of no box,
// or one written before it gave the corners' px).
std::optional<DetectionReport> readDetectionReport(const nlohmann::json& fields);

}  // namespace pw::edit
