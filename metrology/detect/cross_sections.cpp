#include "metrology/detect/cross_sections.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include "metrology/detect/geometry.h"

namespace pw::metrology::detect {
namespace {

constexpr double kStepPx = 0.5;         // scan step in t
constexpr double kMinSideCoverage = 0.3;
// A far wall with one side hidden (a person before a far corner, an open end's floor
// running on, a white wall under a white ceiling): its other three each seen along
// kMinThreeSideCoverage or more, scored on them less kHiddenSidePenalty, and only where
// no section with four sides scores kHiddenSideBelowScore. TUNE 0-599, the sections on
// the angular profile's boundaries where those lie on the true ones (355 scenes): the
// true far wall was not the best scored in 136, in 60 of them with one side under
// kMinSideCoverage; scored this way, the best is the true one in 41 more and 2 fewer
// (within 4 working pixels along the boundaries). Without the bar on the four-sided
// score, penalties 0.1-0.3 and least coverages 0.5-0.85 gained 17-47 and lost 3-50; a
// bar of 1.0 lost TUNE 84 (a far wall seen all round, its boundaries running on no more
// beyond it than inside: 0.99) to a section with a hidden foot.
constexpr double kMinThreeSideCoverage = 0.5;
constexpr double kHiddenSidePenalty = 0.1;
constexpr double kHiddenSideBelowScore = 0.95;
// Above that bar, a section with a side hidden still competes where it scores this much
// more than the best four-sided one: an open end, whose walls and ceiling stop and whose
// floor runs on into a hall (no foot to see), the boundaries running on from its corners,
// against the hall's far wall inside it, seen all round with the boundaries running on
// from nothing (TUNE 402 and 551: 1.55 and 1.39 against 1.07 and 0.96). TUNE 0-599: 0.2
// gained 3 clean and 2 noisy answers and lost none; 0.1 gained 4 and 3, lost 1 noisy;
// 0.3 gained 2 and 1.
constexpr double kHiddenSideOverFour = 0.2;
// Two scans' far walls this near (working pixels along the floor-left boundary) are the
// same section.
constexpr double kSamePlacePx = 3.0;
// The far wall's score (its sides' edge coverage plus how much more the boundaries run
// on beyond its corners than inside them) at its least; below kClearFarWallScore
// (cross_sections.h) the answer is a guess.
constexpr double kMinFarWallScore = 0.8;
// A far wall's side shorter than this (working pixels) has under 10 samples to judge its
// edge by: a section of a few pixels at the vanishing point (a lamp's end, noise) scores
// full coverage and wins (TUNE seed 112: a 3 x 4 px "far wall" for one 200 x 140 px).
// TUNE 0-599 (true far walls 21 px across or more): 8, 10 and 12 each gained the same 4
// clean answers and lost none, noisy +1/-1, +1/-2 and +2/-1; 20 gained 7 but would
// miss a long corridor's far end.
constexpr double kMinFarWallSidePx = 12.0;
constexpr double kMarkedMinSide = 0.6;
// Below this sine (about 11.5 degrees) two lines cross too glancingly to place a corner
// by; the cross-section takes it another way round.
constexpr double kGlancingSine = 0.2;
constexpr double kMarkedMinMean = 0.75;

// Whether an edge runs along `normal`'s perpendicular at p, within 2 pixels of it: a
// gradient across it over the edge threshold (bilinear; for the samples along the rays
// from the vanishing point). `alongOnly`: and within about 27 degrees of square to it,
// so that only edges running along the ray count, not those it crosses (a textured far
// wall's joints, a band across it).
bool edgeAlong(const WorkingImage& image, glm::dvec2 p, glm::dvec2 normal, bool alongOnly) {
  const glm::dvec2 along(normal.y, -normal.x);
  for (double k = -2.0; k <= 2.0; k += 1.0) {
    const glm::dvec2 g = image.gradient(p + k * normal);
    const double across = std::abs(glm::dot(g, normal));
    if (across > kEdgeGreyPerPx && (!alongOnly || std::abs(glm::dot(g, along)) < 0.5 * across)) return true;
  }
  return false;
}

double sideCoverage(const WorkingImage& image, glm::dvec2 a, glm::dvec2 b) {
  const double length = glm::length(b - a);
  if (length < 3) return 0;
  const glm::dvec2 along = (b - a) / length;
  const glm::dvec2 normal(-along.y, along.x);
  // The ends meet other edges (the boundaries): keep to the side's middle 80%.
  int samples = 0, covered = 0;
  for (double s = 0.1 * length; s <= 0.9 * length; s += 1.0) {
    covered += image.edgeNear(a + s * along, normal);
    ++samples;
  }
  return samples > 0 ? static_cast<double>(covered) / samples : 0.0;
}

// How strong a step runs along a-b: the mean over its middle 80% of the strongest
// gradient across it within a pixel (grey levels per pixel).
double sideStrength(const WorkingImage& image, glm::dvec2 a, glm::dvec2 b) {
  const double length = glm::length(b - a);
  if (length < 3) return 0;
  const glm::dvec2 along = (b - a) / length, normal(-along.y, along.x);
  double sum = 0;
  int samples = 0;
  for (double s = 0.1 * length; s <= 0.9 * length; s += 1.0, ++samples) {
    double strongest = 0;
    for (double k = -1.0; k <= 1.0; k += 0.5) {
      strongest = std::max(strongest, std::abs(glm::dot(image.gradient(a + s * along + k * normal), normal)));
    }
    sum += strongest;
  }
  return samples > 0 ? sum / samples : 0.0;
}

// Edge indicator along one boundary ray, one sample per working pixel of radius,
// as a prefix sum so any stretch's coverage is one subtraction.
struct RayEdges {
  std::vector<int> prefix{0};
  double coverage(double from, double to) const {
    const int n = static_cast<int>(prefix.size()) - 1;
    const int a = std::clamp(static_cast<int>(from), 0, n), b = std::clamp(static_cast<int>(to), 0, n);
    return b > a ? static_cast<double>(prefix[b] - prefix[a]) / (b - a) : 0.0;
  }
};

RayEdges rayEdges(const WorkingImage& image, glm::dvec2 vp, glm::dvec2 dir, bool alongOnly) {
  RayEdges edges;
  const glm::dvec2 normal(-dir.y, dir.x);
  const double end = distanceToBorder(image, vp, dir);
  for (double r = 0; r < end; r += 1.0) {
    edges.prefix.push_back(edges.prefix.back() + edgeAlong(image, vp + r * dir, normal, alongOnly));
  }
  return edges;
}

CrossSectionMatch evaluate(const WorkingImage& image, const Quad& q, double t) {
  CrossSectionMatch m;
  m.t = t;
  m.corners = q;
  for (int side = 0; side < 4; ++side) {
    m.sideCoverage[side] = sideCoverage(image, q[kSideCorners[side][0]], q[kSideCorners[side][1]]);
  }
  return m;
}

double shortestSide(const Quad& q) {
  double least = std::numeric_limits<double>::infinity();
  for (const auto& [a, b] : kSideCorners) least = std::min(least, glm::length(q[a] - q[b]));
  return least;
}

// The mean of the k largest of v (v sorted, largest first, in place).
double meanOfBest(std::array<double, 4>& v, int k) {
  std::sort(v.begin(), v.end(), std::greater<>());
  double mean = 0;
  for (int i = 0; i < k; ++i) mean += v[i] / k;
  return mean;
}

double meanOf(const std::array<double, 4>& v) { return (v[0] + v[1] + v[2] + v[3]) / 4; }
double minOf(const std::array<double, 4>& v) { return *std::min_element(v.begin(), v.end()); }

}  // namespace

CrossSectionFamily::CrossSectionFamily(glm::dvec2 vanishingPoint, glm::dvec3 horizontal, glm::dvec3 vertical,
                                       const RecedingBoundaries& boundaries)
    : vp_(vanishingPoint), horizontal_(horizontal), vertical_(vertical) {
  for (int b = 0; b < kBoundaryCount; ++b) rayDirection_[b] = boundaries.direction(b);
}

std::optional<Quad> CrossSectionFamily::at(double t) const {
  const glm::dvec3 vp = homogeneous(vp_);
  // The corner on `boundary`'s ray where the line from `from` towards `towards` (the
  // horizontal or vertical point) crosses it, with how well the two cross (the sine of
  // their angle: a crossing at a glancing angle moves far with a small error in either).
  struct Crossing {
    glm::dvec2 p;
    double sine;
  };
  const auto cross = [&](int boundary, glm::dvec2 from, glm::dvec3 towards) -> std::optional<Crossing> {
    const glm::dvec2 dir = rayDirection_[boundary];
    auto p = intersect(glm::cross(vp, homogeneous(vp_ + dir)), glm::cross(homogeneous(from), towards));
    if (!p || glm::dot(*p - vp_, dir) <= 0) return std::nullopt;
    return Crossing{*p, std::abs(cross2(dir, directionTowards(towards, from)))};
  };
  const glm::dvec2 bottomLeft = vp_ + t * rayDirection_[kFloorLeft];
  const auto bottomRight = cross(kFloorRight, bottomLeft, horizontal_);
  auto topLeft = cross(kCeilingLeft, bottomLeft, vertical_);
  if (!bottomRight) return std::nullopt;
  // A left side seen nearly along its boundaries (the camera close to the left wall, the
  // vanishing point on the far wall's left side): the top-left corner is where the top
  // through the top-right corner crosses the ceiling's ray, round the right side.
  if (!topLeft || topLeft->sine < kGlancingSine) {
    const auto right = cross(kCeilingRight, bottomRight->p, vertical_);
    const auto round = right ? cross(kCeilingLeft, right->p, horizontal_) : std::nullopt;
    if (round && std::min(right->sine, round->sine) > (topLeft ? topLeft->sine : 0.0)) topLeft = round;
  }
  if (!topLeft) return std::nullopt;
  auto topRightA = cross(kCeilingRight, topLeft->p, horizontal_);
  auto topRightB = cross(kCeilingRight, bottomRight->p, vertical_);
  if (!topRightA || !topRightB) return std::nullopt;
  glm::dvec2 topRight = 0.5 * (topRightA->p + topRightB->p);
  if (std::min(topRightA->sine, topRightB->sine) < kGlancingSine) {
    topRight = topRightA->sine > topRightB->sine ? topRightA->p : topRightB->p;
  }
  return Quad{topLeft->p, topRight, bottomLeft, bottomRight->p};
}

double CrossSectionFamily::largestInside(cv::Size size, double marginPx) const {
  // Corners move monotonically outwards with t: bisect on "all inside".
  const auto inside = [&](double t) {
    auto q = at(t);
    if (!q) return false;
    for (const glm::dvec2& p : *q)
      if (p.x < marginPx || p.y < marginPx || p.x > size.width - 1 - marginPx || p.y > size.height - 1 - marginPx) return false;
    return true;
  };
  double lo = 0, hi = std::hypot(size.width, size.height);
  if (!inside(1.0)) return 0;
  lo = 1.0;
  for (int i = 0; i < 50; ++i) {
    const double mid = 0.5 * (lo + hi);
    (inside(mid) ? lo : hi) = mid;
  }
  return lo;
}

namespace {

// The far-wall scan over t in [tFrom, tTo]: the best-scoring section (the middle of
// its plateau), or nullopt when no section there has edges on all four sides (three,
// with `allowHidden`, one side then taken as hidden). `sidesSeen`: how many of the four
// sides must be edges (the best ones scored).
std::optional<CrossSectionMatch> scanFarWall(const WorkingImage& image, const CrossSectionFamily& family, double tFrom,
                                             double tTo, int sidesSeen = 4, bool allowHidden = false) {
  const double tMax = family.largestInside(image.bgr.size(), 2.0);
  tTo = std::min(tTo, tMax);
  std::optional<Quad> outer = family.at(tMax);
  if (tMax < 4 || !outer) return std::nullopt;
  constexpr std::array<int, kBoundaryCount> kCornerOfBoundary = {2, 3, 0, 1};
  const glm::dvec2 vp = family.vanishingPoint();
  std::vector<CrossSectionMatch> sections;
  for (double t = std::max(3.0, tFrom); t <= tTo; t += kStepPx) {
    auto q = family.at(t);
    if (q && shortestSide(*q) >= kMinFarWallSidePx) sections.push_back(evaluate(image, *q, t));
  }
  if (sections.empty()) return std::nullopt;

  // The sections scored with the edges along the rays (`alongOnly`) or with every edge
  // the rays meet: each on its four sides and, where one may be hidden, on its best
  // three. The best one (the middle of its plateau: the edge maps are a pixel wide on
  // either side, so the best score is a plateau a few steps long), or nullopt.
  const auto best = [&](bool alongOnly) -> std::optional<CrossSectionMatch> {
    std::array<RayEdges, kBoundaryCount> rays;
    for (int b = 0; b < kBoundaryCount; ++b) {
      rays[b] = rayEdges(image, vp, glm::normalize((*outer)[kCornerOfBoundary[b]] - vp), alongOnly);
    }
    std::vector<CrossSectionMatch> scan = sections;
    std::vector<double> onThree(scan.size(), -1);  // -1 where three sides do not show
    double bestOnFour = -1;
    for (size_t i = 0; i < scan.size(); ++i) {
      CrossSectionMatch& m = scan[i];
      m.score = -1;
      std::array<double, 4> sorted = m.sideCoverage;
      const double seen = meanOfBest(sorted, sidesSeen);
      const bool allSeen = sorted[sidesSeen - 1] >= kMinSideCoverage;
      const bool threeSeen = allowHidden && sorted[2] >= kMinThreeSideCoverage;
      if (!allSeen && !threeSeen) continue;
      double outside = 0, inside = 0;
      for (int b = 0; b < kBoundaryCount; ++b) {
        const double r = glm::length(m.corners[kCornerOfBoundary[b]] - vp);
        outside += rays[b].coverage(r + 2, r + 2 + std::max(10.0, 0.5 * r));
        inside += rays[b].coverage(0.5 * r, r - 2);
      }
      m.boundaryContrast = (outside - inside) / kBoundaryCount;
      if (allSeen) m.score = seen + m.boundaryContrast;
      if (threeSeen) onThree[i] = meanOfBest(sorted, 3) + m.boundaryContrast - kHiddenSidePenalty;
      bestOnFour = std::max(bestOnFour, m.score);
    }
    // Only where no section shows four sides clearly, or by a clear margin, does one with
    // a side hidden compete.
    for (size_t i = 0; i < scan.size(); ++i) {
      if (bestOnFour >= kHiddenSideBelowScore && onThree[i] < bestOnFour + kHiddenSideOverFour) continue;
      if (onThree[i] <= scan[i].score) continue;
      const auto& c = scan[i].sideCoverage;
      scan[i].score = onThree[i];
      scan[i].hiddenSide = static_cast<int>(std::min_element(c.begin(), c.end()) - c.begin());
    }
    size_t top = 0;
    for (size_t i = 0; i < scan.size(); ++i)
      if (scan[i].score > scan[top].score) top = i;
    if (scan[top].score < 0) return std::nullopt;
    size_t first = top, last = top;
    while (first > 0 && scan[first - 1].score >= scan[top].score - 0.02) --first;
    while (last + 1 < scan.size() && scan[last + 1].score >= scan[top].score - 0.02) ++last;
    return scan[(first + last) / 2];
  };
  // Which section: the edges along the rays decide (with every edge counted, a textured
  // far wall's joints, which the rays cross, made the boundaries seem to run on inside
  // the true far wall and a section farther in won). Where exactly: where both agree on
  // the section, every edge's plateau places it, as before (placed by the new score, the
  // project's corridors' widths moved by up to 0.7%: corridor_h).
  const auto chosen = best(/*alongOnly=*/true);
  if (!chosen) return std::nullopt;
  const auto placed = best(/*alongOnly=*/false);
  if (placed && std::abs(placed->t - chosen->t) <= kSamePlacePx) return placed;
  return chosen;
}

}  // namespace

Result<CrossSectionMatch> findFarWall(const WorkingImage& image, const CrossSectionFamily& family) {
  if (family.largestInside(image.bgr.size(), 2.0) < 4) return makeError("the corridor's boundaries leave the photo at once");
  const auto best = scanFarWall(image, family, 3.0, std::numeric_limits<double>::infinity(), 4, /*allowHidden=*/true);
  if (!best || best->score < kMinFarWallScore) {
    return makeError(kNoFarWallAcrossBoundaries);
  }
  return *best;
}

std::optional<CrossSectionMatch> findFarWallNear(const WorkingImage& image, const CrossSectionFamily& family,
                                                 double tCentre, double reach) {
  return scanFarWall(image, family, tCentre - reach, tCentre + reach, /*sidesSeen=*/3);
}

std::optional<CrossSectionMatch> fitFarWallNear(const WorkingImage& image, glm::dvec2 vp, glm::dvec3 horizontal,
                                                glm::dvec3 vertical, const Quad& rough, double reach) {
  constexpr int kCandidates = 5;  // a checkered floor's tile joints below the foot are edges too
  // Where the person put each side counts a little: of two edges that bear a box out
  // about equally (a ceiling's edge and a lit band's below it), the nearer is taken.
  constexpr double kPlacedWeight = 0.2;
  // Of two edges a side could be on, the stronger step is more likely the wall's own (a
  // ceiling meeting a lit wall, against a faint band on the wall below it).
  constexpr double kStrengthWeight = 0.4;
  // Each side's candidates: lines through its point, offset across the side put, where
  // their edge coverage over the stretch put shows an edge (the kCandidates best).
  struct Candidate {
    glm::dvec3 line;
    double offset;    // from where it was put, in reaches
    double strength;  // its step's strength over the strongest candidate's on its side
  };
  std::array<std::vector<Candidate>, 4> candidates;
  for (int side = 0; side < 4; ++side) {
    const glm::dvec2 a = rough[kSideCorners[side][0]], b = rough[kSideCorners[side][1]];
    const glm::dvec3 point = side < 2 ? horizontal : vertical;
    const glm::dvec2 along = glm::normalize(b - a), normal(-along.y, along.x), middle = 0.5 * (a + b);
    std::vector<double> offsets, coverage, strength;
    for (double d = -reach; d <= reach; d += kStepPx) {
      const glm::dvec3 line = lineThrough(homogeneous(middle + d * normal), point);
      const auto onLine = [&](glm::dvec2 p) { return p - glm::dot(line, homogeneous(p)) * glm::dvec2(line.x, line.y); };
      offsets.push_back(d);
      coverage.push_back(sideCoverage(image, onLine(a), onLine(b)));
      strength.push_back(sideStrength(image, onLine(a), onLine(b)));
    }
    // Each stretch of lines with edges along the side gives the line at its inner end
    // (the far wall's own edge: beyond it a textured floor or wall may keep the edges
    // going, as refineCrossSection takes the innermost edge too), a pixel out from where
    // the edge map starts; its strength the strongest step within 2 px of there.
    const glm::dvec2 centre = 0.25 * (rough[0] + rough[1] + rough[2] + rough[3]);
    const double inward = glm::dot(centre - middle, normal) > 0 ? 1.0 : -1.0;
    const int n = static_cast<int>(coverage.size()), onePx = static_cast<int>(std::lround(1.0 / kStepPx));
    std::vector<std::array<double, 3>> peaks;  // coverage, strength, offset
    for (int i = 0; i < n;) {
      if (coverage[i] < kMinSideCoverage) {
        ++i;
        continue;
      }
      int j = i;
      while (j + 1 < n && coverage[j + 1] >= kMinSideCoverage) ++j;
      const int inner = inward > 0 ? std::max(i, j - onePx) : std::min(j, i + onePx);
      double best = 0, most = 0;
      for (int k = std::max(i, inner - 2 * onePx); k <= std::min(j, inner + 2 * onePx); ++k) {
        best = std::max(best, strength[k]), most = std::max(most, coverage[k]);
      }
      peaks.push_back({most, best, offsets[inner]});
      i = j + 1;
    }
    std::sort(peaks.begin(), peaks.end(), std::greater<>());
    if (peaks.size() > kCandidates) peaks.resize(kCandidates);
    double strongest = 0;
    for (const auto& [c, g, d] : peaks) strongest = std::max(strongest, g);
    for (const auto& [c, g, d] : peaks) {
      candidates[side].push_back({lineThrough(homogeneous(middle + d * normal), point), d / reach, g / strongest});
    }
    if (candidates[side].empty()) return std::nullopt;
  }
  // The boundary through a corner: the share of the ray just beyond the corner with an
  // edge running along it, less the share just inside it, as scanFarWall weighs it
  // (only edges that run along the ray: where the boundaries themselves do not show, the
  // edges the rays cross, a band across the far wall or a pipe, would pass for them).
  const auto runsOn = [&](glm::dvec2 corner) {
    const double r = glm::length(corner - vp);
    if (r < 4) return -1.0;
    const glm::dvec2 dir = (corner - vp) / r, normal(-dir.y, dir.x);
    const double end = distanceToBorder(image, vp, dir);
    const auto share = [&](double from, double to) {
      to = std::min(to, end);
      int samples = 0, along = 0;
      for (double s = from; s < to; s += 1.0, ++samples) along += edgeAlong(image, vp + s * dir, normal, /*alongOnly=*/true);
      return samples > 0 ? static_cast<double>(along) / samples : 0.0;
    };
    return share(r + 2, r + 2 + std::max(10.0, 0.5 * r)) - share(0.5 * r, r - 2);
  };
  // Each corner's boundary support, once per pair of sides that make it.
  const auto corners = [&](int a, int b) {
    std::vector<std::vector<std::pair<glm::dvec2, double>>> at(candidates[a].size());
    for (size_t i = 0; i < candidates[a].size(); ++i) {
      for (const Candidate& other : candidates[b]) {
        const auto p = intersect(candidates[a][i].line, other.line);
        at[i].push_back(p ? std::pair{*p, runsOn(*p)} : std::pair{glm::dvec2(0), -2.0});
      }
    }
    return at;
  };
  const auto topLeft = corners(kTopSide, kLeftSide), topRight = corners(kTopSide, kRightSide),
             bottomLeft = corners(kBottomSide, kLeftSide), bottomRight = corners(kBottomSide, kRightSide);
  std::optional<CrossSectionMatch> best;
  std::array<int, 4> counts{};
  for (int side = 0; side < 4; ++side) counts[side] = static_cast<int>(candidates[side].size());
  forEachChoice(counts, [&](const std::array<int, 4>& c) {
    const auto& [p1, on1] = topLeft[c[kTopSide]][c[kLeftSide]];
    const auto& [p2, on2] = topRight[c[kTopSide]][c[kRightSide]];
    const auto& [p3, on3] = bottomLeft[c[kBottomSide]][c[kLeftSide]];
    const auto& [p4, on4] = bottomRight[c[kBottomSide]][c[kRightSide]];
    if (std::min({on1, on2, on3, on4}) < -1.5) return;  // sides that do not cross
    CrossSectionMatch m = evaluate(image, Quad{p1, p2, p3, p4}, glm::length(p3 - vp));
    m.boundaryContrast = (on1 + on2 + on3 + on4) / 4;
    double moved = 0, strength = 0;
    for (int side = 0; side < 4; ++side) {
      const Candidate& chosen = candidates[side][c[side]];
      moved += chosen.offset * chosen.offset, strength += chosen.strength;
    }
    std::array<double, 4> sides = m.sideCoverage;
    m.score = meanOfBest(sides, 3) + m.boundaryContrast - kPlacedWeight * moved / 4 + kStrengthWeight * strength / 4;
    if (!best || m.score > best->score) best = m;
  });
  return best;
}

double nearestSection(const CrossSectionFamily& family, const Quad& q, double tFrom, double tTo) {
  double bestT = tFrom, bestCost = std::numeric_limits<double>::infinity();
  for (double t = std::max(0.5, tFrom); t <= tTo; t += 0.25) {
    auto at = family.at(t);
    if (!at) continue;
    double cost = 0;
    for (int k = 0; k < 4; ++k) cost += glm::dot((*at)[k] - q[k], (*at)[k] - q[k]);
    if (cost < bestCost) bestCost = cost, bestT = t;
  }
  return bestT;
}

namespace {

// The marked sections (all four sides on image edges, a local maximum of the score
// within 3 px) over t in [tFrom, tTo], nearest the far wall first, each at the inner
// end of its plateau (a band's far edge comes first; the edge maps reach a pixel
// beyond each edge, so the plateau starts a pixel short of it).
std::vector<CrossSectionMatch> markedSections(const WorkingImage& image, const CrossSectionFamily& family, double tFrom,
                                              double tTo) {
  const double tMax = family.largestInside(image.bgr.size(), 2.0);
  std::vector<CrossSectionMatch> scan;
  for (double t = std::max(1.0, tFrom); t <= std::min(tTo, tMax); t += kStepPx) {
    auto q = family.at(t);
    if (!q) continue;
    CrossSectionMatch m = evaluate(image, *q, t);
    m.score = meanOf(m.sideCoverage);
    scan.push_back(m);
  }
  const size_t kOnePixel = static_cast<size_t>(std::lround(1.0 / kStepPx));
  std::vector<CrossSectionMatch> marked;
  for (size_t i = 0; i < scan.size(); ++i) {
    const CrossSectionMatch& m = scan[i];
    if (minOf(m.sideCoverage) < kMarkedMinSide || m.score < kMarkedMinMean) continue;
    bool isPeak = true;
    for (size_t j = i > 6 ? i - 6 : 0; j < std::min(scan.size(), i + 7); ++j) isPeak &= scan[j].score <= m.score;
    if (isPeak) marked.push_back(scan[std::min(i + kOnePixel, scan.size() - 1)]);
  }
  return marked;
}

}  // namespace

std::optional<CrossSectionMatch> findMarkedCrossSection(const WorkingImage& image, const CrossSectionFamily& family,
                                                        double farWallT) {
  // The deepest marked section.
  auto marked = markedSections(image, family, 1.2 * farWallT, std::numeric_limits<double>::infinity());
  if (marked.empty()) return std::nullopt;
  return marked.front();
}

std::optional<CrossSectionMatch> findMarkedCrossSectionNear(const WorkingImage& image, const CrossSectionFamily& family,
                                                            double tCentre, double reach) {
  auto marked = markedSections(image, family, tCentre - reach, tCentre + reach);
  if (marked.empty()) return std::nullopt;
  return *std::max_element(marked.begin(), marked.end(),
                           [](const CrossSectionMatch& a, const CrossSectionMatch& b) { return a.score < b.score; });
}

}  // namespace pw::metrology::detect
