// Snapping a corner a person drags onto the edge junction it belongs to (issue 22
// part 5): the editor shows the snap while the drag goes on and puts the corner there
// on release (Alt keeps it where it is).
//
//   const CornerSnapper snapper(photo, focalPx, principalPoint, shot.distortion);   // per photo and camera
//   if (auto at = snapper.snap(P1, shot.cornersPx, dragged, 12.0)) ...
#pragma once

#include <array>
#include <optional>

#include <glm/glm.hpp>
#include <opencv2/core/mat.hpp>

#include "metrology/distortion.h"

namespace pw::metrology::detect {

struct CornerSnap {
  glm::dvec2 px{0, 0};    // where the corner goes (the photo's pixels)
  double confidence = 0;  // the fitted corner's (detect.h's CornerEstimate)
};

class CornerSnapper {
 public:
  // `photoBgr` is shared, not copied (a cv::Mat header). `lens`: the shot's distortion
  // when it has one (the photo is read through it), else none: fitted to the photo's
  // straight lines, as detect does.
  CornerSnapper(const cv::Mat& photoBgr, double focalPx, glm::dvec2 principalPointPx,
                std::optional<RadialDistortion> lens = std::nullopt)
      : photo_(photoBgr), focalPx_(focalPx), principalPointPx_(principalPointPx), lens_(lens) {}

  // Corner `corner` (P1..P8) of `box` dropped at `at`: the box fitted to the photo's
  // edges and vanishing points from there (detect's hint: the far wall's sides through
  // the horizontal and vertical points, the boundaries through the corridor's), and
  // where that puts this corner, when it is within `reachPx` of `at` and the photo bears
  // it out; nullopt otherwise. The other corners are not changed. A detection's cost
  // (about 0.1 s for 0.5 MP): the editor asks on a worker thread while dragging.
  std::optional<CornerSnap> snap(int corner, std::array<glm::dvec2, 8> box, glm::dvec2 at, double reachPx) const;

 private:
  cv::Mat photo_;
  double focalPx_ = 0;
  glm::dvec2 principalPointPx_{0, 0};
  std::optional<RadialDistortion> lens_;
};

}  // namespace pw::metrology::detect
