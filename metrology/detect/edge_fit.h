// Sub-pixel fitting of straight image edges at full resolution.
#pragma once

#include <optional>

#include <glm/glm.hpp>
#include <opencv2/core/mat.hpp>

#include "metrology/corridor_frame.h"

namespace pw::metrology::detect {

// The photo as the full-resolution fits see it: a pinhole image of the photo's size,
// read bilinearly. Through a lens, a pinhole pixel is read where the lens put it in
// the photo (one interpolation, and the photo is never undistorted whole: on 12 MP
// that remap alone cost more than the rest of detection).
class PinholeView {
 public:
  explicit PinholeView(const cv::Mat& photo) : photo_(photo) {}
  PinholeView(const cv::Mat& photo, const Intrinsics& lens) : photo_(photo), lens_(lens) {}
  cv::Size size() const { return photo_.size(); }
  bool empty() const { return photo_.empty(); }
  // The colour (B, G, R) at pinhole pixel p; reads beyond the photo's edge take its
  // nearest pixel.
  glm::dvec3 colour(glm::dvec2 p) const;

 private:
  cv::Mat photo_;  // CV_8UC3 (a header: the pixels are shared)
  std::optional<Intrinsics> lens_;
};

struct EdgeLine {
  glm::dvec3 line{0, 0, 0};  // normalised homogeneous line: l·(u, v, 1) is a signed distance in pixels
  double rmsPx = 0;          // RMS distance of the inlier edge points from the line
  double coverage = 0;       // share of the samples that found an edge and agreed with the line
  int inliers = 0;
  // 1-sigma uncertainty of the line's position, in pixels, at the middle of the
  // fitted stretch: rms / sqrt(inliers) (at least 0.05 px).
  double positionSigmaPx() const;
};

struct EdgeSearch {
  glm::dvec2 from, to;      // the stretch of the initial line to sample (full-resolution pixels)
  glm::dvec3 through;       // homogeneous point every candidate line passes through (may be at infinity)
  double searchPx = 4;      // how far either side of the initial line to look for the edge, at `from`
  double searchGrowPx = 0;  // ... plus this much more at `to` (linearly): for rays whose angle is uncertain
  double stepHalfWidthPx = 2;  // each side's width in the step response (a Haar-like step filter)
  int maxSamples = 400;
  // Among the edges at least this share as strong as the strongest in the window,
  // take the one nearest the initial line: a tile joint 3 px beside a far wall's foot
  // must not win by contrast alone, nor a band's outer edge where its inner edge
  // borders a dark tile.
  double minRelativeStrength = 0.5;
  // When set, the edge is the one farthest towards this point (a section's inside: the
  // far wall's own edge before any on the surface beyond it) rather than the one
  // nearest the initial line, in each sample and in the fit, which starts from the
  // innermost line a quarter of the samples agree on (fitEdgeLine).
  std::optional<glm::dvec2> innerPoint;
};

// Finds the edge along each of up to maxSamples normals to the stretch from..to
// (a peak of the difference between the mean colours of the `stepHalfWidthPx`
// pixels on either side, chosen as EdgeSearch says and placed to sub-pixel by a
// parabola through the response), then
// fits the line through `through` that minimises the squared distances, with
// outliers (texture edges, occlusions) dropped by a MAD rule over the points it
// follows. With `innerPoint`, when the samples' edges split between lines 1.5 px or
// more apart that a quarter of them each lie on, the fit starts from the innermost: where
// the section's own edge is faint in some samples, they take the next edge beyond,
// and a line through all of them would fall between the two. nullopt when fewer
// than 5 samples found an edge.
std::optional<EdgeLine> fitEdgeLine(const PinholeView& photo, const EdgeSearch& search);

}  // namespace pw::metrology::detect
