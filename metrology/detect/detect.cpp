#include "metrology/detect/detect.h"

#include <algorithm>
#include <cmath>

#include "metrology/detect/boundaries.h"
#include "metrology/detect/cross_sections.h"
#include "metrology/detect/distortion.h"
#include "metrology/detect/geometry.h"
#include "metrology/detect/line_segments.h"
#include "metrology/detect/refine.h"
#include "metrology/detect/working_image.h"

namespace pw::metrology::detect {
namespace {

constexpr double kMinSegmentLengthOfDiagonal = 0.02;
// A corridor's vanishing point has receding lines arriving from most directions
// (floor, both walls, ceiling): below this (see estimateManhattanFrame) it is the
// meeting point of a few unrelated lines.
constexpr double kMinCorridorConfidence = 0.15;
constexpr int kMinPhotoSidePx = 32;
// Inlier segments of a true vanishing point agree with it to a degree or so (the
// five test corridors: 0.2-1.1); a "point" fitted to unrelated lines does not.
constexpr double kMaxCorridorRmsAngleDeg = 2.0;
// A boundary must follow an edge over a quarter of its outer half at least (people
// or furniture may hide the rest).
constexpr double kMinBoundaryEdgeCoverage = 0.25;
// Each far-wall side must be an edge over this share of its middle stretch.
constexpr double kMinFarSideCoverage = 0.3;

CorridorDetection notFound(CorridorDetection d, const std::string& reason) {
  d.found = false;
  d.notFoundReason = reason;
  return d;
}

// The quad's corners are in the order top-left, top-right, bottom-left,
// bottom-right; it must be convex and contain `inside`.
bool convexAround(const Quad& q, glm::dvec2 inside) {
  const std::array<glm::dvec2, 4> ring = {q[0], q[1], q[3], q[2]};  // clockwise on screen
  for (int i = 0; i < 4; ++i) {
    const glm::dvec2 a = ring[i], b = ring[(i + 1) % 4];
    const double cross = (b.x - a.x) * (inside.y - a.y) - (b.y - a.y) * (inside.x - a.x);
    if (!(cross > 0)) return false;
  }
  return true;
}

bool allFinite(const std::array<CornerEstimate, 8>& corners) {
  for (const CornerEstimate& c : corners)
    if (!std::isfinite(c.px.x) || !std::isfinite(c.px.y) || !std::isfinite(c.confidence)) return false;
  return true;
}

Result<ManhattanFrame> frameWithFocal(const std::vector<LineSegment>& segments, double focalPx, glm::dvec2 pp,
                                      cv::Size size) {
  return estimateManhattanFrame(segments, PinholeCamera{focalPx, pp}, size);
}

}  // namespace

const char* focalSourceName(FocalSource source) {
  switch (source) {
    case FocalSource::kGiven: return "given";
    case FocalSource::kVanishingPoints: return "vanishing_points";
    case FocalSource::kDefault: return "default";
  }
  return "?";
}

const char* nearDepthName(NearDepth depth) {
  return depth == NearDepth::kMarkedCrossSection ? "marked_cross_section" : "image_edge";
}

Result<CorridorDetection> detectCorridor(const cv::Mat& photo, const DetectOptions& options) {
  if (photo.empty() || photo.type() != CV_8UC3) return makeError("detect needs an 8-bit colour photo");
  if (photo.cols < kMinPhotoSidePx || photo.rows < kMinPhotoSidePx) {
    return makeError("the photo is " + std::to_string(photo.cols) + "x" + std::to_string(photo.rows) +
                     " pixels; detection needs at least " + std::to_string(kMinPhotoSidePx) + " on each side");
  }
  if (options.focalPx && !(*options.focalPx > 0 && std::isfinite(*options.focalPx))) {
    return makeError("the focal length must be a positive number of pixels");
  }
  const cv::Size size = photo.size();
  const glm::dvec2 pp = options.principalPointPx.value_or(glm::dvec2((size.width - 1) * 0.5, (size.height - 1) * 0.5));
  if (!(pp.x >= 0 && pp.y >= 0 && pp.x <= size.width - 1 && pp.y <= size.height - 1)) {
    return makeError("the principal point must lie inside the " + std::to_string(size.width) + "x" +
                     std::to_string(size.height) + " photo");
  }
  const double diagonal = std::hypot(size.width, size.height);

  CorridorDetection d;
  d.principalPointPx = pp;
  const WorkingImage work = makeWorkingImage(photo, std::max(kMinPhotoSidePx, options.workingMaxSidePx));
  const std::vector<LineSegment> segments = detectLineSegments(work.gray, work.scale, kMinSegmentLengthOfDiagonal * diagonal);
  d.segmentCount = static_cast<int>(segments.size());
  if (options.estimateDistortion) {
    const double focalPx = options.focalPx.value_or(kDefaultFocalOverLongSide * std::max(size.width, size.height));
    if (auto lens = fitPlumbLines(work, segments, pp, focalPx)) return detectThroughLens(photo, options, *lens);
  }

  // Vanishing points, and the focal length when it is not given.
  d.focalSource = options.focalPx ? FocalSource::kGiven : FocalSource::kDefault;
  d.focalPx = options.focalPx.value_or(kDefaultFocalOverLongSide * std::max(size.width, size.height));
  auto frame = frameWithFocal(segments, d.focalPx, pp, size);
  if (!frame) return notFound(d, frame.message());
  if (!options.focalPx) {
    std::optional<double> f = focalFromOrthogonalPoints(frame->corridor, frame->horizontal, pp, diagonal);
    if (!f) f = focalFromOrthogonalPoints(frame->corridor, frame->vertical, pp, diagonal);
    const double longSide = std::max(size.width, size.height);
    if (f && *f > 0.3 * longSide && *f < 5.0 * longSide) {
      d.focalPx = *f;
      d.focalSource = FocalSource::kVanishingPoints;
      frame = frameWithFocal(segments, d.focalPx, pp, size);
      if (!frame) return notFound(d, frame.message());
    } else {
      d.warnings.push_back("focal length not given and the photo has no second finite vanishing point: assumed " +
                           std::to_string(static_cast<int>(std::lround(d.focalPx))) +
                           " px (a 28 mm-equivalent lens); lengths along the corridor scale with it");
    }
  }
  d.corridor = frame->corridor;
  d.horizontal = frame->horizontal;
  d.vertical = frame->vertical;
  const glm::dvec2 vp = d.corridor.pixel();
  if (!(vp.x >= 0 && vp.y >= 0 && vp.x <= size.width - 1 && vp.y <= size.height - 1)) {
    return notFound(d, "the lines meet outside the photo, not at a corridor's end");
  }
  if (d.corridor.rmsAngleDeg > kMaxCorridorRmsAngleDeg) {
    return notFound(d, "the receding lines do not meet in one point (rms " +
                           std::to_string(d.corridor.rmsAngleDeg).substr(0, 4) + " degrees)");
  }
  if (d.corridor.confidence < kMinCorridorConfidence) {
    return notFound(d, "too few receding lines around the vanishing point (confidence " +
                           std::to_string(d.corridor.confidence).substr(0, 4) + ")");
  }

  // Boundaries and the far wall on the working copy.
  const glm::dvec2 vpWork = work.toWorking(vp);
  const glm::dvec2 horizon = directionTowards(d.horizontal.point, vp);
  auto boundaries = findRecedingBoundaries(work, vpWork, std::atan2(horizon.y, horizon.x));
  if (!boundaries) return notFound(d, boundaries.message());
  for (int b = 0; b < kBoundaryCount; ++b) {
    if (boundaries->edgeCoverage[b] < kMinBoundaryEdgeCoverage) {
      return notFound(d, std::string("no edge along the ") + boundaryName(b) + " boundary");
    }
  }
  const CrossSectionFamily family(vpWork, work.toWorking(d.horizontal.point), work.toWorking(d.vertical.point), *boundaries);
  auto farWall = findFarWall(work, family);
  if (!farWall) return notFound(d, farWall.message());

  // Full resolution: far wall sides, then the boundaries beyond it.
  const double searchPx = 2.0 / work.scale + 2.0;
  const double stepHalfWidthPx = std::max(2.0, 1.0 / work.scale);
  Quad coarseFar;
  for (int k = 0; k < 4; ++k) coarseFar[k] = work.toFull(farWall->corners[k]);
  const RefinedSection far = refineCrossSection(photo, coarseFar, d.horizontal.point, d.vertical.point, searchPx, stepHalfWidthPx);
  for (int side = 0; side < 4; ++side) {
    if (!far.sideFitted[side] || far.sides[side].coverage < kMinFarSideCoverage) {
      static const char* const kSideNames[4] = {"top", "bottom", "left", "right"};
      return notFound(d, std::string("the far wall's ") + kSideNames[side] + " edge is not in the photo");
    }
  }
  if (!convexAround(far.corners, vp)) return notFound(d, "the far wall's corners do not surround the vanishing point");
  for (int k = 0; k < 4; ++k) {
    d.corners[k] = {far.corners[k], far.cornerConfidence[k], far.cornerSigmaPx[k]};
    if (!(far.corners[k].x >= 0 && far.corners[k].y >= 0 && far.corners[k].x <= size.width - 1 &&
          far.corners[k].y <= size.height - 1)) {
      return notFound(d, "the far wall's corners fall outside the photo");
    }
  }
  // The boundaries run from the vanishing point through the far wall's corners:
  // those corners, fitted to a tenth of a pixel about a hundred pixels out, fix the
  // rays' angles better than the angular profile did (a mortar joint one course
  // below the ceiling can pull that by half a degree).
  constexpr std::array<int, kBoundaryCount> kFarCornerOf = {2, 3, 0, 1};  // P3 P4 P1 P2
  RecedingBoundaries throughCorners = *boundaries;
  std::array<glm::dvec2, kBoundaryCount> cornerDirection{};
  std::array<double, kBoundaryCount> fromRadius{};
  for (int b = 0; b < kBoundaryCount; ++b) {
    const glm::dvec2 corner = far.corners[kFarCornerOf[b]];
    cornerDirection[b] = glm::normalize(corner - vp);
    throughCorners.angle[b] = std::atan2(cornerDirection[b].y, cornerDirection[b].x);
    fromRadius[b] = 1.1 * glm::length(corner - vp) + 2.0;
  }
  // Fitted beyond the far wall, the rays say how well the image bears them out.
  const auto rays = refineBoundaries(photo, vp, cornerDirection, fromRadius, searchPx, stepHalfWidthPx);
  const CrossSectionFamily nearFamily(vpWork, work.toWorking(d.horizontal.point), work.toWorking(d.vertical.point),
                                      throughCorners);

  // P5..P8: on a marked cross-section (band, frame) when there is one, else at the
  // nearest depth where all four stay inside the photo (the editor moves them).
  std::optional<CrossSectionMatch> marked;
  if (!options.nearAtImageEdge) marked = findMarkedCrossSection(work, nearFamily, farWall->t);
  constexpr std::array<int, 4> kNearCornerOfQuad = {6, 7, 4, 5};  // P7 P8 P5 P6
  if (marked) {
    Quad coarseNear;
    for (int k = 0; k < 4; ++k) coarseNear[k] = work.toFull(marked->corners[k]);
    // A band has two edges a few pixels apart and the scan stops at the first, its
    // far (inner) one: a one-pixel step keeps the two apart, and a low bar keeps the
    // inner edge where it borders a tile nearly as dark as the band.
    const RefinedSection nearSection = refineCrossSection(photo, coarseNear, d.horizontal.point, d.vertical.point,
                                                          searchPx, std::max(1.0, 1.0 / work.scale), 0.25);
    for (int k = 0; k < 4; ++k) {
      d.corners[kNearCornerOfQuad[k]] = {nearSection.corners[k], nearSection.cornerConfidence[k], nearSection.cornerSigmaPx[k]};
    }
    d.nearDepth = NearDepth::kMarkedCrossSection;
  } else {
    const CrossSectionFamily fullFamily(vp, d.horizontal.point, d.vertical.point, throughCorners);
    const double t = fullFamily.largestInside(size, 0.01 * std::min(size.width, size.height));
    auto q = fullFamily.at(t);
    if (!q || t <= glm::length(far.corners[2] - vp)) return notFound(d, "no room between the far wall and the photo's edge");
    for (int k = 0; k < 4; ++k) {
      const int b = std::array{kCeilingLeft, kCeilingRight, kFloorLeft, kFloorRight}[k];
      // On a fitted boundary the corner's sideways position is measured; its depth is
      // a convention, so it gets half that line's confidence.
      const double confidence = rays[b].fit ? 0.5 * std::min(1.0, rays[b].fit->coverage) : 0.1;
      const double sigma = rays[b].fit ? rays[b].fit->positionSigmaPx() : searchPx;
      d.corners[kNearCornerOfQuad[k]] = {(*q)[k], confidence, sigma};
    }
    d.nearDepth = NearDepth::kImageEdge;
  }
  if (!allFinite(d.corners)) return notFound(d, "the fitted corners are degenerate");
  d.found = true;
  return d;
}

}  // namespace pw::metrology::detect
