// Lens distortion from the photo's straight lines: the plumb-line method (Brown,
// "Close-range camera calibration", 1971; Devernay & Faugeras, "Straight lines have to
// be straight", 2001). Lines that are straight in the world (the corridor's edges,
// mortar and tile joints, frames) are chains of LSD segments in the photo, slightly
// bent by the lens; the radial coefficient k1 that makes them straight again, fitted
// to their sub-pixel edge points, is the lens's. Then detection runs on the pinhole
// image behind the photo (detect.cpp), and its corners are taken back into the photo.
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>
#include <opencv2/core/mat.hpp>

#include "base/result.h"
#include "metrology/corridor_frame.h"
#include "metrology/detect/detect.h"
#include "metrology/detect/line_segments.h"
#include "metrology/detect/working_image.h"

namespace pw::metrology::detect {

struct PlumbLineFit {
  // The lens: the focal length it is normalised by (the one given, or a stand-in: the
  // plumb lines fix k1 / f², and the coefficient is rescaled once the focal length is
  // known), the principal point, and k1 (k2 = 0).
  Intrinsics lens;
  int lineCount = 0;          // the chains of segments fitted
  double rmsBeforePx = 0;     // their edge points' RMS distance from a straight line, as photographed
  double rmsAfterPx = 0;      // the same, undistorted by `lens`
};

// Fits k1 to the long chains of `segments` (full-resolution pixels, LSD's on `work`),
// sampling their edges on `work`. None when the photo has too few long lines, or when
// straightening them does not pay beyond their noise: a photo without visible
// distortion is left a pinhole (detection then runs as it always did).
std::optional<PlumbLineFit> fitPlumbLines(const WorkingImage& work, const std::vector<LineSegment>& segments,
                                          glm::dvec2 principalPointPx, double focalPx);

}  // namespace pw::metrology::detect
