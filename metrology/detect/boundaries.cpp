#include "metrology/detect/boundaries.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <tuple>
#include <vector>

#include "metrology/detect/geometry.h"

namespace pw::metrology::detect {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kBins = 8192;              // 0.044 degree
constexpr int kCoarseWindowBins = 64;    // 2.8 degrees each side: finds the step among textures
constexpr int kFineWindowBins = 8;       // 0.35 degree each side: places it
constexpr double kFineRangeDeg = 1.0;
// footOfBand: a band 0.3-4 degrees across (from the vanishing point), its foot's step at
// least 0.3 as sharp as its top's, its colour kBandGrey from the wall's, the floor's
// beside it and the floor's over kBandFloorDeg beyond (grey levels, as skirtingBelow's),
// and so, in its own colour, at three quarters of kBandPlaces places along the ray.
constexpr double kBandMinDeg = 0.3, kBandMaxDeg = 4.0, kBandStepShare = 0.3, kBandGrey = 12.0, kBandAlongShare = 0.75,
                 kBandFloorDeg = 2.0;
constexpr int kBandPlaces = 8;
constexpr double kQuadrantMarginDeg = 3.0;
constexpr double kMinContrast = 1.0;
// Each quadrant's strongest steps tried together when its heaviest do not make a box,
// and how far (degrees) a boundary may lie from where the other three put it (TUNE
// 0-599: 5 and 6 gained 11 and 9 clean answers but made a wrong answer sure; 8 gained
// 6 clean, 5 noisy, with no wrong sure answer; 12 gained 3 and 3. TUNE 112: a lamp row
// taken for the ceiling's edge lay 44 degrees from where the other three put it).
constexpr size_t kBoundaryCandidates = 3;
constexpr double kBoxAgreementDeg = 8.0;
// A quadrant's steps whose rays show an edge along less than this share of their outer
// half weigh their strength times that share, the others their strength (the heaviest
// step is the boundary). TUNE 0-599 against strength alone: +3/-0 clean (361, 380,
// 561), +1/-0 noisy (458), "no corridor" with the box in view 29 -> 27 and 31 -> 29.
// Every step weighed by its coverage (a share of 1): +4/-0 and +2/-1, but the project's
// clutter_6 lost its floor-left boundary to a step edged all along 20 degrees off (its true
// one is not among the steps; the half-edged one taken before, 4 degrees off, was mended
// by the later fits).
constexpr double kFullWeightCoverage = 0.5;
// RecedingBoundaries::alternatives: at least this share of the summed weight of the set
// taken (each step weighed as kFullWeightCoverage says; before stop 51, the summed
// strength). Tried wherever the set taken's far wall scored lower (stop 49), the
// alternatives that made a right answer wrong had 0.26-0.78 of it but two, those that
// made a wrong one right 0.79-1.0; findCorridor tries them only where the set taken
// finds no far wall or one with a side hidden, and there weaker ones do no harm: TUNE
// 0-599, 0.8 -> 0.6: +1/-0 clean (198), +1/-0 noisy (476), "no corridor" with the box
// in view 32 -> 29 clean; 0.5 the same as 0.6, 0.7 +1/-0 and 31.
constexpr double kAlternativeWeightShare = 0.6;

// atan2 to about 1e-5 rad (Abramowitz & Stegun 4.4.49-style minimax polynomial),
// several times cheaper than std::atan2 over a million pixels.
inline double fastAtan2(double y, double x) {
  const double ax = std::abs(x), ay = std::abs(y);
  if (ax == 0 && ay == 0) return 0;
  const bool swap = ay > ax;
  const double t = swap ? ax / ay : ay / ax;
  const double t2 = t * t;
  double a = t * (0.99997726 + t2 * (-0.33262347 + t2 * (0.19354346 + t2 * (-0.11643287 + t2 * (0.05265332 - t2 * 0.01172120)))));
  if (swap) a = kPi / 2 - a;
  if (x < 0) a = kPi - a;
  return y < 0 ? -a : a;
}

int binOf(double angle) { return static_cast<int>(wrapAngle(angle) / (2 * kPi) * kBins) % kBins; }
double angleOf(int bin) { return (bin + 0.5) * 2 * kPi / kBins; }

// Per angle bin: summed B, G, R and gradient magnitude of the pixels, and their count.
class AngularProfile {
 public:
  static constexpr int kChannels = 4;
  using Features = std::array<double, kChannels>;

  AngularProfile(const WorkingImage& image, glm::dvec2 vp) {
    std::vector<Features> sum(kBins, Features{});
    std::vector<double> count(kBins, 0.0);
    const double minRadius2 = std::pow(0.02 * std::hypot(image.bgr.cols, image.bgr.rows), 2);
    const double binsPerRadian = kBins / (2 * kPi);
    for (int y = 0; y < image.bgr.rows; ++y) {
      const cv::Vec3b* row = image.bgr.ptr<cv::Vec3b>(y);
      const float* gx = image.gradX.ptr<float>(y);
      const float* gy = image.gradY.ptr<float>(y);
      const double dy = y - vp.y;
      for (int x = 0; x < image.bgr.cols; ++x) {
        const double dx = x - vp.x;
        if (dx * dx + dy * dy < minRadius2) continue;
        const int bin = static_cast<int>(wrapAngle(fastAtan2(dy, dx)) * binsPerRadian) % kBins;
        Features& s = sum[bin];
        s[0] += row[x][0], s[1] += row[x][1], s[2] += row[x][2];
        s[3] += std::abs(gx[x]) + std::abs(gy[x]);
        count[bin] += 1;
      }
    }
    // Prefix sums over three turns make any circular window around a bin of the
    // middle turn one subtraction.
    prefixSum_.assign(3 * kBins + 1, Features{});
    prefixCount_.assign(3 * kBins + 1, 0.0);
    for (int i = 0; i < 3 * kBins; ++i) {
      for (int c = 0; c < kChannels; ++c) prefixSum_[i + 1][c] = prefixSum_[i][c] + sum[i % kBins][c];
      prefixCount_[i + 1] = prefixCount_[i] + count[i % kBins];
    }
    // Each channel's spread over all angles is its unit; a floor of a few grey
    // levels keeps a flat channel from amplifying noise.
    const double total = prefixCount_[kBins];
    Features mean{};
    for (int c = 0; c < kChannels; ++c) mean[c] = prefixSum_[kBins][c] / std::max(total, 1.0);
    Features var{};
    for (int b = 0; b < kBins; ++b) {
      if (count[b] <= 0) continue;
      for (int c = 0; c < kChannels; ++c) {
        const double d = sum[b][c] / count[b] - mean[c];
        var[c] += count[b] * d * d;
      }
    }
    for (int c = 0; c < kChannels; ++c) spread_[c] = std::max(std::sqrt(var[c] / std::max(total, 1.0)), 4.0);
  }

  // Mean colour (B, G, R) of the bins between `from` and `to` (either order, any
  // integers: wrapped), or nullopt where they hold too few pixels.
  std::optional<glm::dvec3> meanColour(int from, int to) const {
    if (to <= from) std::swap(from, to);
    const int a = (from % kBins + kBins) % kBins + kBins, b = a + (to - from);
    if (b > 3 * kBins) return std::nullopt;
    const double n = count(a, b);
    if (n < 20) return std::nullopt;
    return glm::dvec3(prefixSum_[b][0] - prefixSum_[a][0], prefixSum_[b][1] - prefixSum_[a][1],
                      prefixSum_[b][2] - prefixSum_[a][2]) / n;
  }

  // Distance between the mean features of the `window` bins before and after the
  // boundary at the start of `bin`, in units of each channel's spread. Colour only
  // when `colourOnly`: an edge's own gradient band (Sobel spreads it over three
  // pixels) would otherwise pull a narrow step towards the smoother side.
  double step(int bin, int window, bool colourOnly = false) const {
    // Into the middle turn, so both b - window and b + window stay in the arrays.
    const int b = (bin % kBins + kBins) % kBins + kBins;
    const double nl = count(b - window, b), nr = count(b, b + window);
    if (nl < 20 || nr < 20) return 0;
    double d2 = 0;
    for (int c = 0; c < (colourOnly ? 3 : kChannels); ++c) {
      const double l = (prefixSum_[b][c] - prefixSum_[b - window][c]) / nl;
      const double r = (prefixSum_[b + window][c] - prefixSum_[b][c]) / nr;
      const double d = (l - r) / spread_[c];
      d2 += d * d;
    }
    return std::sqrt(d2);
  }

 private:
  double count(int from, int to) const { return prefixCount_[to] - prefixCount_[from]; }
  std::vector<Features> prefixSum_;
  std::vector<double> prefixCount_;
  Features spread_{};
};

// The angle of the sharpest colour step within `range` bins of `coarseBin`: narrow
// windows are not misled by a texture line beside a boundary (a mortar joint one brick
// course below a ceiling), which only a gradient would prefer. The bin's start is the step.
double sharpestStepAngle(const AngularProfile& profile, int coarseBin, int range) {
  double fineStrength = -1;
  int fineBin = coarseBin;
  for (int i = -range; i <= range; ++i) {
    const int bin = (coarseBin + i + kBins) % kBins;
    const double s = profile.step(bin, kFineWindowBins, /*colourOnly=*/true);
    if (s > fineStrength) fineStrength = s, fineBin = bin;
  }
  return wrapAngle(angleOf(fineBin) - 0.5 * 2 * kPi / kBins);
}

}  // namespace

const char* boundaryName(int boundary) {
  static const char* const kNames[kBoundaryCount] = {"floor-left", "floor-right", "ceiling-left", "ceiling-right"};
  return boundary >= 0 && boundary < kBoundaryCount ? kNames[boundary] : "?";
}

double distanceToBorder(const WorkingImage& image, glm::dvec2 origin, glm::dvec2 direction) {
  const double w = image.bgr.cols - 1, h = image.bgr.rows - 1;
  double t = std::numeric_limits<double>::infinity();
  if (direction.x > 1e-12) t = std::min(t, (w - origin.x) / direction.x);
  if (direction.x < -1e-12) t = std::min(t, -origin.x / direction.x);
  if (direction.y > 1e-12) t = std::min(t, (h - origin.y) / direction.y);
  if (direction.y < -1e-12) t = std::min(t, -origin.y / direction.y);
  return std::isfinite(t) ? std::max(t, 0.0) : 0.0;
}

double rayEdgeCoverage(const WorkingImage& image, glm::dvec2 vp, double angle) {
  const glm::dvec2 dir(std::cos(angle), std::sin(angle));
  const glm::dvec2 normal(-dir.y, dir.x);
  const double end = distanceToBorder(image, vp, dir) - 2.0;
  int samples = 0, covered = 0;
  for (double r = 0.45 * end; r <= end; r += 1.0) {
    // The strongest gradient within a pixel of the ray, across it.
    double across = 0;
    for (double k = -1; k <= 1; k += 1)
      across = std::max(across, std::abs(glm::dot(image.gradient(vp + r * dir + k * normal), normal)));
    covered += across > kEdgeGreyPerPx;
    ++samples;
  }
  return samples > 0 ? static_cast<double>(covered) / samples : 0.0;
}

std::optional<double> impliedBoundaryAngle(const RecedingBoundaries& rays, int missing, glm::dvec2 vp,
                                           glm::dvec3 horizontal, glm::dvec3 vertical) {
  const auto ray = [&](int b) { return lineThrough(vp, vp + rays.direction(b)); };
  const auto towards = [](glm::dvec2 p, glm::dvec3 point) { return glm::cross(homogeneous(p), point); };
  constexpr double kRadius = 100.0;  // any: the sections of a box are one another's images
  std::optional<glm::dvec2> p1, p2, p3, p4;
  if (missing == kFloorLeft) {
    p1 = vp + kRadius * rays.direction(kCeilingLeft);
    p2 = intersect(towards(*p1, horizontal), ray(kCeilingRight));
    if (p2) p4 = intersect(towards(*p2, vertical), ray(kFloorRight));
    if (p4) p3 = intersect(towards(*p4, horizontal), towards(*p1, vertical));
  } else {
    p3 = vp + kRadius * rays.direction(kFloorLeft);
    if (missing != kFloorRight) p4 = intersect(towards(*p3, horizontal), ray(kFloorRight));
    if (missing != kCeilingLeft) p1 = intersect(towards(*p3, vertical), ray(kCeilingLeft));
    if (missing == kFloorRight && p1) {
      p2 = intersect(towards(*p1, horizontal), ray(kCeilingRight));
      if (p2) p4 = intersect(towards(*p3, horizontal), towards(*p2, vertical));
    } else if (missing == kCeilingLeft && p4) {
      p2 = intersect(towards(*p4, vertical), ray(kCeilingRight));
      if (p2) p1 = intersect(towards(*p2, horizontal), towards(*p3, vertical));
    } else if (missing == kCeilingRight && p1 && p4) {
      p2 = intersect(towards(*p1, horizontal), towards(*p4, vertical));
    }
  }
  const std::array<std::optional<glm::dvec2>, kBoundaryCount> corner = {p3, p4, p1, p2};
  if (!corner[missing]) return std::nullopt;
  const glm::dvec2 d = *corner[missing] - vp;
  return std::atan2(d.y, d.x);
}

Result<RecedingBoundaries> findRecedingBoundaries(const WorkingImage& image, glm::dvec2 vp, double horizonAngle,
                                                  std::optional<std::pair<glm::dvec3, glm::dvec3>> sectionPoints) {
  if (!image.contains(vp, 1.0)) return makeError("the corridor's vanishing point lies outside the photo");
  const AngularProfile profile(image, vp);

  // Quadrants measured from the horizon: floor-right (0..90 degrees, v grows down),
  // floor-left, ceiling-left, ceiling-right. In each, its strongest steps (peaks of the
  // coarse step, the strongest first).
  constexpr std::array<int, kBoundaryCount> kQuadrantOf = {1, 0, 2, 3};
  std::array<std::vector<std::pair<double, int>>, kBoundaryCount> peaks;  // strength, bin
  int missing = -1;
  const auto notFound = [](int b) {
    return makeError(std::string("no ") + boundaryName(b) + " boundary (floor, walls and ceiling look alike)");
  };
  for (int boundary = 0; boundary < kBoundaryCount; ++boundary) {
    const double q0 = horizonAngle + kQuadrantOf[boundary] * kPi / 2;
    const double margin = kQuadrantMarginDeg * kPi / 180;
    const int first = binOf(q0 + margin);
    const int span = static_cast<int>((kPi / 2 - 2 * margin) / (2 * kPi) * kBins);
    std::vector<double> step(span + 1);
    for (int i = 0; i <= span; ++i) step[i] = profile.step((first + i) % kBins, kCoarseWindowBins);
    double strongest = -1;
    int strongestBin = first;
    for (int i = 0; i <= span; ++i) {
      if (step[i] > strongest) strongest = step[i], strongestBin = (first + i) % kBins;
    }
    if (strongest < kMinContrast) {
      // One quadrant without a step (a floor the walls' colour) is where the other three
      // put it; two are not found.
      if (missing >= 0 || !sectionPoints) return notFound(missing >= 0 ? missing : boundary);
      missing = boundary;
      continue;
    }
    peaks[boundary].push_back({strongest, strongestBin});
    for (int i = 0; i <= span; ++i) {
      // Other peaks: the strongest within a coarse window either side, a window apart
      // from the strongest.
      if (step[i] < kMinContrast || std::abs(i - (strongestBin - first + kBins) % kBins) <= kCoarseWindowBins) continue;
      bool peak = true;
      for (int j = std::max(0, i - kCoarseWindowBins); j <= std::min(span, i + kCoarseWindowBins) && peak; ++j) {
        peak = step[j] < step[i] || (step[j] == step[i] && j >= i);
      }
      if (peak) peaks[boundary].push_back({step[i], (first + i) % kBins});
    }
    std::sort(peaks[boundary].begin() + 1, peaks[boundary].end(), std::greater<>());
    if (peaks[boundary].size() > kBoundaryCandidates) peaks[boundary].resize(kBoundaryCandidates);
  }
  // Each step placed (the sharpest step near the coarse one: narrow windows are not
  // misled by a texture line beside the boundary, a mortar joint one brick course below a
  // ceiling, which only a gradient would prefer) and its ray's edge coverage, once per step:
  // the weights and the alternatives below share them.
  std::array<std::array<std::optional<std::pair<double, double>>, kBoundaryCandidates>, kBoundaryCount> placedSteps;
  const auto placed = [&](int boundary, int i) {
    auto& p = placedSteps[boundary][i];
    if (!p) {
      const double angle = sharpestStepAngle(profile, peaks[boundary][i].second, static_cast<int>(kFineRangeDeg / 360.0 * kBins));
      p.emplace(angle, rayEdgeCoverage(image, vp, angle));
    }
    return *p;  // angle, edge coverage
  };
  // A step whose ray shows an edge along less than kFullWeightCoverage of its outer half
  // weighs its strength times that share: a wall meeting the floor or the ceiling is an
  // edge all along, while a row of lamps along the ceiling or a wall's shading steps the
  // profile's colour with little edge along it.
  const auto weightOf = [&](int boundary, int i) {
    const double coverage = placed(boundary, i).second;
    return peaks[boundary][i].first * (coverage >= kFullWeightCoverage ? 1.0 : coverage);
  };
  // The heaviest steps, unless they do not make a box and another set of them does.
  std::array<int, kBoundaryCount> pick{};
  for (int boundary = 0; boundary < kBoundaryCount; ++boundary) {
    if (boundary == missing) continue;
    for (int i = 1; i < static_cast<int>(peaks[boundary].size()); ++i) {
      if (weightOf(boundary, i) > weightOf(boundary, pick[boundary])) pick[boundary] = i;
    }
  }
  std::vector<std::pair<double, std::array<int, kBoundaryCount>>> boxes;  // every set that makes a box, with its weight
  const auto weightOfSet = [&](const std::array<int, kBoundaryCount>& choice) {
    double weight = 0;
    for (int b = 0; b < kBoundaryCount; ++b) weight += weightOf(b, choice[b]);
    return weight;
  };
  if (sectionPoints) {
    const auto [horizontal, vertical] = *sectionPoints;
    const auto agreement = [&](const std::array<int, kBoundaryCount>& choice) {
      RecedingBoundaries rays;
      for (int b = 0; b < kBoundaryCount; ++b) rays.angle[b] = angleOf(peaks[b][choice[b]].second);
      double worst = 0;
      for (int b = 0; b < kBoundaryCount; ++b) {
        const auto implied = impliedBoundaryAngle(rays, b, vp, horizontal, vertical);
        if (!implied) return kPi;
        worst = std::max(worst, std::abs(std::remainder(*implied - rays.angle[b], 2 * kPi)));
      }
      return worst;
    };
    const double agree = kBoxAgreementDeg * kPi / 180;
    if (missing < 0) {
      std::array<int, kBoundaryCount> counts{};
      for (int b = 0; b < kBoundaryCount; ++b) counts[b] = static_cast<int>(peaks[b].size());
      forEachChoice(counts, [&](const std::array<int, kBoundaryCount>& c) {
        if (agreement(c) <= agree) boxes.push_back({weightOfSet(c), c});
      });
      std::stable_sort(boxes.begin(), boxes.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
      if (agreement(pick) > agree && !boxes.empty()) pick = boxes.front().second;
    }
  }
  RecedingBoundaries out;
  for (int boundary = 0; boundary < kBoundaryCount; ++boundary) {
    if (boundary == missing) continue;
    std::tie(out.angle[boundary], out.edgeCoverage[boundary]) = placed(boundary, pick[boundary]);
    out.contrast[boundary] = peaks[boundary][pick[boundary]].first;
  }
  // The one boundary that does not show, where the other three put it: its quadrant has
  // no step, or it is the only one with no edge along it (a floor's skirting hidden by
  // benches, white on white).
  const auto imply = [&](int b) {
    const auto implied = impliedBoundaryAngle(out, b, vp, sectionPoints->first, sectionPoints->second);
    if (!implied) return false;
    out.angle[b] = *implied;
    out.edgeCoverage[b] = rayEdgeCoverage(image, vp, *implied);
    out.implied = b;
    return true;
  };
  if (missing >= 0) {
    if (!imply(missing)) return notFound(missing);
  } else if (sectionPoints) {
    int edgeless = -1, count = 0;
    for (int b = 0; b < kBoundaryCount; ++b) {
      if (out.edgeCoverage[b] < kMinBoundaryEdgeCoverage) edgeless = b, ++count;
    }
    if (count == 1) imply(edgeless);
  }
  // (boxes is empty where a quadrant showed no step: `pick` has no weight then.)
  const double leastWeight = boxes.empty() ? 0.0 : kAlternativeWeightShare * weightOfSet(pick);
  for (const auto& [weight, choice] : boxes) {
    if (choice == pick || weight < leastWeight) continue;
    RecedingBoundaries alternative;
    bool edges = true;
    for (int b = 0; b < kBoundaryCount && edges; ++b) {
      std::tie(alternative.angle[b], alternative.edgeCoverage[b]) = placed(b, choice[b]);
      alternative.contrast[b] = peaks[b][choice[b]].first;
      edges = alternative.edgeCoverage[b] >= kMinBoundaryEdgeCoverage;
    }
    if (edges) out.alternatives.push_back(std::move(alternative));
  }
  return out;
}

namespace {

// A floor boundary found at a band's top (a skirting board's, along the walls): the
// step beyond it, away from the horizon, where the band ends on the floor. Looked for
// within kBandMaxDeg of `angle` (the step found, radians); taken at the first step at
// least kBandStepShare as sharp, a local maximum, where the band's mean colour differs
// from the wall's inside it and the floor's beyond it by kBandGrey or more, and does so,
// in one colour, at kBandAlongShare of the places sampled along the ray's outer half (a
// board runs along the wall; a checkered floor's first row of tiles is two colours:
// corridor_e). TUNE 0-599: +5/-1 clean, +3/-0 noisy (open ends whose feet sat on the
// side boards' tops: 157, 161, 258, 420, 525); at half the places and without the wider
// floor's test, +11/-2 and +10/-2, but the project's corridor_b and corridor_e lost
// their feet to a plank and a row of tiles.
std::optional<double> footOfBand(const WorkingImage& image, const AngularProfile& profile, glm::dvec2 vp, double angle,
                                 double horizonAngle) {
  const int fb = binOf(angle + 0.5 * 2 * kPi / kBins);
  const auto offHorizon = [&](int bin) { return std::abs(std::sin(angleOf(bin) - horizonAngle)); };
  const int out = offHorizon(fb + 10) > offHorizon(fb - 10) ? 1 : -1;
  const double found = profile.step(fb, kFineWindowBins, true);
  const int minSep = static_cast<int>(kBandMinDeg / 360.0 * kBins), maxSep = static_cast<int>(kBandMaxDeg / 360.0 * kBins);
  for (int k = minSep; k <= maxSep; ++k) {
    const int bin = fb + out * k;
    const double sharp = profile.step(bin, kFineWindowBins, true);
    if (sharp < kBandStepShare * found) continue;
    if (sharp < profile.step(bin - 1, kFineWindowBins, true) || sharp < profile.step(bin + 1, kFineWindowBins, true)) continue;
    const auto wall = profile.meanColour(fb - out * kFineWindowBins, fb);
    const auto band = profile.meanColour(fb + out * 2, bin - out * 2);
    const auto floor = profile.meanColour(bin, bin + out * kFineWindowBins);
    if (!wall || !band || !floor || glm::length(*band - *wall) < kBandGrey || glm::length(*band - *floor) < kBandGrey) continue;
    // Nor like the floor further out (a wooden floor's first plank: corridor_b).
    const auto floorWide = profile.meanColour(bin, bin + out * static_cast<int>(kBandFloorDeg / 360.0 * kBins));
    if (!floorWide || glm::length(*band - *floorWide) < kBandGrey) continue;
    // Along the ray's outer half: the band unlike the wall and the floor in most places.
    const double aWall = angleOf(fb), aFloor = angleOf(bin), aBand = 0.5 * (aWall + aFloor);
    const double halfBand = 0.5 * std::abs(aFloor - aWall);
    const double reach = distanceToBorder(image, vp, {std::cos(aBand), std::sin(aBand)});
    const auto colourAt = [&](double a, double r) -> std::optional<glm::dvec3> {
      const glm::dvec2 q = vp + r * glm::dvec2(std::cos(a), std::sin(a));
      if (!image.contains(q, 1)) return std::nullopt;
      const cv::Vec3b c = image.bgr.at<cv::Vec3b>(static_cast<int>(q.y + 0.5), static_cast<int>(q.x + 0.5));
      return glm::dvec3(c[0], c[1], c[2]);
    };
    const double sign = aFloor > aWall ? 1.0 : -1.0;
    std::vector<std::array<glm::dvec3, 3>> places;  // wall, band, floor
    for (int i = 0; i < kBandPlaces; ++i) {
      const double r = reach * (0.5 + 0.45 * i / (kBandPlaces - 1));
      const double margin = std::max(2.0 / r, halfBand);
      const auto w = colourAt(aWall - sign * margin, r), b = colourAt(aBand, r), f = colourAt(aFloor + sign * margin, r);
      if (w && b && f) places.push_back({*w, *b, *f});
    }
    if (places.size() < kBandPlaces / 2) continue;
    // The band's colour where it is typical (the middle of its samples by brightness):
    // a board is one colour along the wall, a checkered floor's first row of tiles two.
    std::vector<glm::dvec3> bands;
    for (const auto& p : places) bands.push_back(p[1]);
    std::nth_element(bands.begin(), bands.begin() + bands.size() / 2, bands.end(),
                     [](const glm::dvec3& a, const glm::dvec3& b) { return a.x + a.y + a.z < b.x + b.y + b.z; });
    const glm::dvec3 typical = bands[bands.size() / 2];
    int shown = 0;
    for (const auto& [w, b, f] : places) {
      if (glm::length(b - w) >= kBandGrey && glm::length(b - f) >= kBandGrey && glm::length(b - typical) < kBandGrey) ++shown;
    }
    if (shown < kBandAlongShare * places.size()) continue;
    return wrapAngle(angleOf((bin % kBins + kBins) % kBins) - 0.5 * 2 * kPi / kBins);
  }
  return std::nullopt;
}

}  // namespace

RecedingBoundaries boundariesNear(const WorkingImage& image, glm::dvec2 vp, const std::array<double, kBoundaryCount>& angle,
                                  const std::array<double, kBoundaryCount>& reachRad, std::optional<double> horizonAngle) {
  const AngularProfile profile(image, vp);
  RecedingBoundaries out;
  for (int boundary = 0; boundary < kBoundaryCount; ++boundary) {
    // The strongest step within reach (the same coarse window as the whole search),
    // then placed by the sharpest colour step within a degree of it.
    const int centre = binOf(angle[boundary]);
    const int reach = std::max(1, static_cast<int>(reachRad[boundary] / (2 * kPi) * kBins));
    double coarseStrength = -1;
    int coarseBin = centre;
    for (int i = -reach; i <= reach; ++i) {
      const int bin = (centre + i + kBins) % kBins;
      const double s = profile.step(bin, kCoarseWindowBins);
      if (s > coarseStrength) coarseStrength = s, coarseBin = bin;
    }
    out.contrast[boundary] = std::max(coarseStrength, 0.0);
    if (coarseStrength < kMinContrast) {
      out.angle[boundary] = wrapAngle(angle[boundary]);  // nothing to go by: as given
    } else {
      out.angle[boundary] =
          sharpestStepAngle(profile, coarseBin, std::min(reach, static_cast<int>(kFineRangeDeg / 360.0 * kBins)));
    }
    if (horizonAngle && boundary <= kFloorRight && coarseStrength >= kMinContrast) {
      if (auto below = footOfBand(image, profile, vp, out.angle[boundary], *horizonAngle)) {
        out.angle[boundary] = *below;
        out.belowBand[boundary] = true;
      }
    }
    out.edgeCoverage[boundary] = rayEdgeCoverage(image, vp, out.angle[boundary]);
  }
  return out;
}

}  // namespace pw::metrology::detect
