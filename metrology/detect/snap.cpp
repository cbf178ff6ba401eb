#include "metrology/detect/snap.h"

#include <algorithm>
#include <cmath>

#include "metrology/detect/detect.h"
#include "metrology/shot.h"

namespace pw::metrology::detect {

std::optional<CornerSnap> CornerSnapper::snap(int corner, std::array<glm::dvec2, 8> box, glm::dvec2 at,
                                              double reachPx) const {
  if (corner < 0 || corner >= kCornerCount || photo_.empty() || !(reachPx > 0)) return std::nullopt;
  box[corner] = at;
  DetectOptions options;
  if (focalPx_ > 0) options.focalPx = focalPx_;
  options.principalPointPx = principalPointPx_;
  options.lens = lens_;
  options.hintPx = box;
  options.hintReachPx = std::max(reachPx, 6.0);
  options.hintWeighsDetection = false;
  auto fitted = detectCorridor(photo_, options);
  if (!fitted || !fitted->found) return std::nullopt;
  const CornerEstimate& c = fitted->corners[corner];
  // Confidence 0: the photo did not bear the box out (the corners came back as given).
  if (!(c.confidence > 0) || glm::length(c.px - at) > reachPx) return std::nullopt;
  return CornerSnap{c.px, c.confidence};
}

}  // namespace pw::metrology::detect
