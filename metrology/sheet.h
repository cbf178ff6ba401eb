// The measurement sheet: a picture of the measurement a person would rather look at
// than read (after the seed paper's figure 11).
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <opencv2/core/mat.hpp>

#include "base/result.h"
#include "metrology/measure.h"
#include "metrology/shot.h"

namespace pw::metrology {

// Draws, on a copy of `photo` (8-bit, 1, 3 or 4 channels; widened with a margin
// where corners or the vanishing point lie outside it, up to one image size each
// way): the five plane outlines, the corners P1..P8 as clicked (circles, labelled)
// and as fitted (crosses), the receding edges extended to the vanishing point VP,
// the horizon, and each dimension written along its edge with its ± (width on
// P5-P6, height on P6-P8, length on P5-P3); for the seed method also the paper's
// ground line GL with the floor corners extended to it; plus a legend with the camera and the
// reprojection error in a strip below. Returns a BGR image. Fails only on an empty
// photo or one of another pixel type.
//
// `points` (named, the photo's pixels) are drawn as small rings with their names, and
// `objects` (a measured distance or height between two of them) as a line with the
// text written along it (object_measure.h; `measure --point ... --sheet`).
struct SheetPoint {
  std::string name;
  glm::dvec2 px{0.0};
};
struct SheetObject {
  glm::dvec2 fromPx{0.0}, toPx{0.0};
  std::string text;  // "H 1.78 m +/- 0.02" (the Hershey font has no ±)
};
Result<cv::Mat> drawMeasurementSheet(const cv::Mat& photo, const Shot& shot, const Measurement& measurement,
                                     const std::vector<SheetPoint>& points = {},
                                     const std::vector<SheetObject>& objects = {});

}  // namespace pw::metrology
