#include "metrology/detect/refine.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "metrology/detect/geometry.h"

namespace pw::metrology::detect {
namespace {

double distanceToBorder(cv::Size size, glm::dvec2 origin, glm::dvec2 dir) {
  double t = std::numeric_limits<double>::infinity();
  if (dir.x > 1e-12) t = std::min(t, (size.width - 1 - origin.x) / dir.x);
  if (dir.x < -1e-12) t = std::min(t, -origin.x / dir.x);
  if (dir.y > 1e-12) t = std::min(t, (size.height - 1 - origin.y) / dir.y);
  if (dir.y < -1e-12) t = std::min(t, -origin.y / dir.y);
  return std::isfinite(t) ? std::max(t, 0.0) : 0.0;
}

// Confidence of a corner where two fitted lines meet: both must follow an edge
// over most of their length, and fit it tightly (an rms of 1 px halves it).
double cornerConfidence(const EdgeLine& a, bool fittedA, const EdgeLine& b, bool fittedB) {
  if (!fittedA || !fittedB) return 0.2;
  const double coverage = std::min(a.coverage, b.coverage);
  const double rms = std::max(a.rmsPx, b.rmsPx);
  return std::clamp(coverage, 0.0, 1.0) * std::exp(-rms * std::log(2.0));
}

}  // namespace

RefinedSection refineCrossSection(const PinholeView& photo, const Quad& coarse, glm::dvec3 horizontal,
                                  glm::dvec3 vertical, double searchPx, double stepHalfWidthPx,
                                  double minRelativeStrength, std::optional<glm::dvec2> innerPoint) {
  RefinedSection out;
  std::array<glm::dvec3, 4> lines{};
  for (int side = 0; side < 4; ++side) {
    const glm::dvec2 a = coarse[kSideCorners[side][0]], b = coarse[kSideCorners[side][1]];
    EdgeSearch search;
    // The side's ends meet the boundaries' edges: sample its middle 70%.
    search.from = a + 0.15 * (b - a);
    search.to = a + 0.85 * (b - a);
    search.through = side == kTopSide || side == kBottomSide ? horizontal : vertical;
    search.searchPx = searchPx;
    search.stepHalfWidthPx = stepHalfWidthPx;
    search.minRelativeStrength = minRelativeStrength;
    if (side == kTopSide || side == kBottomSide) search.innerPoint = innerPoint;
    auto fit = fitEdgeLine(photo, search);
    out.sideFitted[side] = fit.has_value();
    if (fit) {
      out.sides[side] = *fit;
      lines[side] = fit->line;
    } else {
      lines[side] = lineThrough(a, b);
      out.sides[side].line = lines[side];
      out.sides[side].rmsPx = searchPx;
      out.sides[side].inliers = 1;
    }
  }
  // Corner k is where its horizontal side meets its vertical side (kCornerSides).
  for (int k = 0; k < 4; ++k) {
    const int h = kCornerSides[k][0], v = kCornerSides[k][1];
    auto p = intersect(lines[h], lines[v]);
    // Far from the coarse corner means the fits went astray: keep the coarse one.
    const bool sane = p && glm::length(*p - coarse[k]) <= 2 * searchPx;
    out.corners[k] = sane ? *p : coarse[k];
    out.cornerConfidence[k] = sane ? cornerConfidence(out.sides[h], out.sideFitted[h], out.sides[v], out.sideFitted[v]) : 0.1;
    out.cornerSigmaPx[k] = sane ? std::hypot(out.sides[h].positionSigmaPx(), out.sides[v].positionSigmaPx()) : searchPx;
  }
  return out;
}

std::array<RefinedBoundary, kBoundaryCount> refineBoundaries(const PinholeView& photo, glm::dvec2 vp,
                                                             const std::array<glm::dvec2, kBoundaryCount>& coarseDirection,
                                                             const std::array<double, kBoundaryCount>& fromRadius,
                                                             double searchPx, double stepHalfWidthPx) {
  std::array<RefinedBoundary, kBoundaryCount> out;
  for (int b = 0; b < kBoundaryCount; ++b) {
    out[b].direction = coarseDirection[b];
    const double end = distanceToBorder(photo.size(), vp, coarseDirection[b]) - 2.0;
    const double start = fromRadius[b];
    if (end - start < 10) continue;
    EdgeSearch search;
    search.from = vp + start * coarseDirection[b];
    search.to = vp + end * coarseDirection[b];
    search.through = homogeneous(vp);
    search.searchPx = searchPx;
    search.searchGrowPx = (end - start) * std::tan(0.3 * 3.14159265358979 / 180);
    search.stepHalfWidthPx = stepHalfWidthPx;
    out[b].fit = fitEdgeLine(photo, search);
    if (out[b].fit) {
      // The fitted line through the vanishing point, oriented outwards like the ray.
      const glm::dvec2 along(-out[b].fit->line.y, out[b].fit->line.x);
      out[b].direction = glm::dot(along, coarseDirection[b]) >= 0 ? along : -along;
    }
  }
  return out;
}

}  // namespace pw::metrology::detect
