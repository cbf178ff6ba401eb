// A picture of what detection found, for people: the photo with the receding
// boundaries, the far wall, the near cross-section and each corner's confidence.
#pragma once

#include <opencv2/core/mat.hpp>

#include "metrology/detect/detect.h"

namespace pw::metrology::detect {

// Returns a copy of `photoBgr` with the detection drawn on it (lines scaled to the
// photo's size). Corners are ringed green (confidence >= 0.7), amber (>= 0.4) or red.
cv::Mat drawDetection(const cv::Mat& photoBgr, const CorridorDetection& detection);

}  // namespace pw::metrology::detect
