#include "metrology/detect/distortion.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include "metrology/distortion.h"
#include "metrology/least_squares.h"

namespace pw::metrology::detect {
namespace {

// Segments shorter than this share of the diagonal say little about a line's bend.
constexpr double kMinSegmentOfDiagonal = 0.025;
// Two segments continue one line when the gap between their ends is at most this
// (share of the diagonal), they turn by at most kMaxTurnDeg, and each end lies within
// kMaxLateralPx (plus the turn over the gap) of the other's line.
constexpr double kMaxGapOfDiagonal = 0.03;
constexpr double kMaxTurnDeg = 4.0;
constexpr double kMaxLateralPx = 1.5;
// A chain used as a plumb line spans at least this share of the diagonal.
constexpr double kMinChainOfDiagonal = 0.1;
constexpr int kMinChainPoints = 24;
constexpr int kMinLines = 5;
// The fitted k1 is kept only when it straightens the lines well beyond their noise:
// each line's squared bend falls by kMinSignificance times its noise on average (the
// ground truth's photos: -3.7 to -0.2 without distortion, 250 to 15700 through k1 =
// -0.1 and -0.2), the lines' summed bend by kMinExplained (0.5% at most without
// distortion, 4.9% to 79% with: brick joints are many and noisy), and the lens moves
// the photo's corner by at least kMinCornerShiftPx (less is below what the corners
// can be placed to).
constexpr double kMinSignificance = 20.0;
constexpr double kMinExplained = 0.02;
constexpr double kMinCornerShiftPx = 1.0;
// The k1 searched (normalised by the stand-in focal length).
constexpr double kMinK1 = -0.6, kMaxK1 = 0.4;
constexpr int kGridSteps = 25;
constexpr int kGoldenSteps = 25;  // the bracket of two grid steps to 1e-5 of it

glm::dvec2 direction(const LineSegment& s) { return (s.b - s.a) / s.lengthPx; }

// Distance of p from the line through segment s.
double lateral(const LineSegment& s, glm::dvec2 p) {
  const glm::dvec2 d = direction(s);
  const glm::dvec2 q = p - s.a;
  return std::abs(d.x * q.y - d.y * q.x);
}

// The end `end` (0: a, 1: b) of s and its outward direction.
glm::dvec2 endPoint(const LineSegment& s, int end) { return end == 0 ? s.a : s.b; }
glm::dvec2 outward(const LineSegment& s, int end) { return end == 0 ? -direction(s) : direction(s); }

// Links each segment end to the best continuing segment end, keeps the links both
// ends agree on, and follows them into chains (lists of segment indices in order).
std::vector<std::vector<int>> chainSegments(const std::vector<LineSegment>& segments, double diagonal) {
  const int n = static_cast<int>(segments.size());
  const double maxGap = kMaxGapOfDiagonal * diagonal;
  const double maxTurnSin = std::sin(glm::radians(kMaxTurnDeg));
  std::vector<std::array<int, 2>> best(n, {-1, -1});  // the other end, as 2 * segment + end
  std::vector<std::array<double, 2>> bestGap(n, {maxGap, maxGap});
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      const glm::dvec2 di = direction(segments[i]), dj = direction(segments[j]);
      if (std::abs(di.x * dj.y - di.y * dj.x) > maxTurnSin) continue;
      for (int ei = 0; ei < 2; ++ei) {
        for (int ej = 0; ej < 2; ++ej) {
          const glm::dvec2 pi = endPoint(segments[i], ei), pj = endPoint(segments[j], ej);
          const double gap = glm::length(pj - pi);
          if (gap >= bestGap[i][ei] && gap >= bestGap[j][ej]) continue;
          // j continues beyond i's end and i beyond j's (no side-by-side overlap).
          if (glm::dot(pj - pi, outward(segments[i], ei)) < -2.0) continue;
          if (glm::dot(pi - pj, outward(segments[j], ej)) < -2.0) continue;
          if (glm::dot(outward(segments[i], ei), outward(segments[j], ej)) > 0) continue;
          const double allowed = kMaxLateralPx + gap * maxTurnSin;
          if (lateral(segments[i], pj) > allowed || lateral(segments[j], pi) > allowed) continue;
          if (gap < bestGap[i][ei]) bestGap[i][ei] = gap, best[i][ei] = 2 * j + ej;
          if (gap < bestGap[j][ej]) bestGap[j][ej] = gap, best[j][ej] = 2 * i + ei;
        }
      }
    }
  }
  // Mutual links only.
  std::vector<std::array<int, 2>> link(n, {-1, -1});
  for (int i = 0; i < n; ++i) {
    for (int e = 0; e < 2; ++e) {
      const int other = best[i][e];
      if (other >= 0 && best[other / 2][other % 2] == 2 * i + e) link[i][e] = other;
    }
  }
  std::vector<bool> used(n, false);
  std::vector<std::vector<int>> chains;
  for (int start = 0; start < n; ++start) {
    if (used[start]) continue;
    // Walk to one end of the chain first, then collect along it.
    int s = start, fromEnd = 0;
    for (int steps = 0; steps < n; ++steps) {
      const int back = link[s][fromEnd];
      if (back < 0 || back / 2 == start) break;
      s = back / 2;
      fromEnd = 1 - back % 2;
    }
    std::vector<int> chain;
    int end = 1 - fromEnd;
    for (int steps = 0; steps <= n && s >= 0 && !used[s]; ++steps) {
      used[s] = true;
      chain.push_back(s);
      const int next = link[s][end];
      if (next < 0) break;
      s = next / 2;
      end = 1 - next % 2;
    }
    chains.push_back(std::move(chain));
  }
  return chains;
}

// Sub-pixel edge points along a segment: at each step the strongest gradient across
// it within a few pixels (a parabola through the peak and its neighbours).
void sampleEdge(const WorkingImage& work, const LineSegment& s, std::vector<glm::dvec2>& out) {
  const glm::dvec2 a = work.toWorking(s.a), b = work.toWorking(s.b);
  const double length = glm::length(b - a);
  if (!(length > 6)) return;
  const glm::dvec2 d = (b - a) / length, n(-d.y, d.x);
  constexpr double kStep = 0.5, kReach = 2.5;
  constexpr int kSamples = static_cast<int>(2 * kReach / kStep) + 1;
  for (double t = 3; t <= length - 3; t += 1.5) {
    const glm::dvec2 c = a + t * d;
    std::array<double, kSamples> g{};
    int peak = 0;
    for (int i = 0; i < kSamples; ++i) {
      g[i] = std::abs(glm::dot(work.gradient(c + (-kReach + i * kStep) * n), n));
      if (g[i] > g[peak]) peak = i;
    }
    if (peak == 0 || peak == kSamples - 1 || g[peak] < 2.0 * kEdgeGreyPerPx) continue;
    const double curvature = g[peak - 1] - 2 * g[peak] + g[peak + 1];
    const double offset = curvature < 0 ? 0.5 * (g[peak - 1] - g[peak + 1]) / curvature : 0.0;
    const glm::dvec2 p = c + (-kReach + (peak + offset) * kStep) * n;
    out.push_back(work.toFull(p));
  }
}

// A chain's edge points normalised by the lens's focal length about its principal
// point, with their radii: what every trial k1 undistorts.
struct NormalisedChain {
  std::vector<glm::dvec2> x;
  std::vector<double> radius;
};

NormalisedChain normalise(const Intrinsics& lens, const std::vector<glm::dvec2>& pointsPx) {
  NormalisedChain n;
  for (const glm::dvec2& p : pointsPx) {
    n.x.push_back((p - lens.principalPointPx) / lens.focalPx);
    n.radius.push_back(glm::length(n.x.back()));
  }
  return n;
}

// The pinhole radius the lens r (1 + k1 r²) takes to `distorted` (Newton's method from
// r = distorted; a few steps converge within the model's one-to-one part).
double undistortedRadius(double k1, double distorted) {
  double r = distorted;
  for (int it = 0; it < 5; ++it) r -= (r * (1.0 + k1 * r * r) - distorted) / (1.0 + 3.0 * k1 * r * r);
  return r;
}

// Sum of squared distances (pixels²) of the chain's points undistorted by k1 from their
// total-least-squares line: the smaller eigenvalue of their scatter.
double straightnessCost(const NormalisedChain& chain, double k1, double focalPx) {
  glm::dvec2 sum(0.0);
  double sxx = 0, sxy = 0, syy = 0;
  for (size_t i = 0; i < chain.x.size(); ++i) {
    const double r = chain.radius[i];
    const glm::dvec2 q = r > 0 ? chain.x[i] * (undistortedRadius(k1, r) / r) : chain.x[i];
    sum += q;
    sxx += q.x * q.x, sxy += q.x * q.y, syy += q.y * q.y;
  }
  const double n = static_cast<double>(chain.x.size());
  const glm::dvec2 mean = sum / n;
  sxx -= n * mean.x * mean.x, sxy -= n * mean.x * mean.y, syy -= n * mean.y * mean.y;
  const double half = 0.5 * (sxx + syy), root = std::sqrt(0.25 * (sxx - syy) * (sxx - syy) + sxy * sxy);
  return std::max(0.0, half - root) * focalPx * focalPx;
}

struct ChainCosts {
  double total = 0;  // summed over the chains
  std::vector<double> perChain;
};

ChainCosts costs(const Intrinsics& lens, double k1, const std::vector<NormalisedChain>& chains) {
  ChainCosts c;
  for (const NormalisedChain& chain : chains) {
    c.perChain.push_back(straightnessCost(chain, k1, lens.focalPx));
    c.total += c.perChain.back();
  }
  return c;
}

// The k1 in [kMinK1, kMaxK1] that makes the chains straightest.
double bestK1(const Intrinsics& lens, const std::vector<NormalisedChain>& chains) {
  return minimizeOnInterval([&](double k1) { return costs(lens, k1, chains).total; }, kMinK1, kMaxK1, kGridSteps,
                            kGoldenSteps, 0.0);
}

size_t pointCount(const std::vector<NormalisedChain>& chains) {
  size_t n = 0;
  for (const NormalisedChain& c : chains) n += c.x.size();
  return n;
}

}  // namespace

std::optional<PlumbLineFit> fitPlumbLines(const WorkingImage& work, const std::vector<LineSegment>& segments,
                                          glm::dvec2 principalPointPx, double focalPx) {
  const double diagonal = std::hypot(work.bgr.cols, work.bgr.rows) / work.scale;
  std::vector<LineSegment> longOnes;
  for (const LineSegment& s : segments) {
    if (s.lengthPx >= kMinSegmentOfDiagonal * diagonal) longOnes.push_back(s);
  }
  PlumbLineFit fit;
  fit.lens.focalPx = focalPx;
  fit.lens.principalPointPx = principalPointPx;
  std::vector<NormalisedChain> chains;
  for (const std::vector<int>& indices : chainSegments(longOnes, diagonal)) {
    std::vector<glm::dvec2> points;
    for (int i : indices) sampleEdge(work, longOnes[i], points);
    if (static_cast<int>(points.size()) < kMinChainPoints) continue;
    double span = 0;
    for (const glm::dvec2& p : points) span = std::max(span, glm::length(p - points.front()));
    if (span < kMinChainOfDiagonal * diagonal) continue;
    chains.push_back(normalise(fit.lens, points));
  }
  if (static_cast<int>(chains.size()) < kMinLines) return std::nullopt;

  // Fit; a photo whose lines no k1 straightens noticeably stops here (most photos).
  double k1 = bestK1(fit.lens, chains);
  const double straight = costs(fit.lens, 0.0, chains).total;
  if (!(costs(fit.lens, k1, chains).total < (1.0 - 0.5 * kMinExplained) * straight)) return std::nullopt;
  // Drop the chains that stay bent (a curve, two lines joined, a wrong link), fit again.
  for (int round = 0; round < 2; ++round) {
    const ChainCosts c = costs(fit.lens, k1, chains);
    std::vector<double> rms;
    for (size_t i = 0; i < chains.size(); ++i) rms.push_back(std::sqrt(c.perChain[i] / chains[i].x.size()));
    std::vector<double> sorted = rms;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    const double limit = std::max(0.3, 3.0 * sorted[sorted.size() / 2]);
    std::vector<NormalisedChain> kept;
    for (size_t i = 0; i < chains.size(); ++i) {
      if (rms[i] <= limit) kept.push_back(std::move(chains[i]));
    }
    const bool dropped = kept.size() < chains.size();
    chains = std::move(kept);
    if (static_cast<int>(chains.size()) < kMinLines) return std::nullopt;
    if (!dropped) break;
    k1 = bestK1(fit.lens, chains);
  }
  fit.lineCount = static_cast<int>(chains.size());
  fit.lens.distortion.k1 = k1;
  // How far the lens moves the photo's farthest corner.
  double shift = 0;
  const glm::dvec2 size(work.bgr.cols / work.scale, work.bgr.rows / work.scale);
  for (const glm::dvec2 corner : {glm::dvec2(0, 0), glm::dvec2(size.x - 1, 0), glm::dvec2(0, size.y - 1), size - 1.0}) {
    shift = std::max(shift, glm::length(distortPixel(fit.lens, corner) - corner));
  }
  // Significance: each line's drop in squared bend over its own noise (an F ratio for
  // one parameter), averaged over the lines; and the share of the bend k1 explains.
  const ChainCosts before = costs(fit.lens, 0.0, chains), after = costs(fit.lens, k1, chains);
  double significance = 0;
  for (size_t i = 0; i < chains.size(); ++i) {
    const double dof = static_cast<double>(chains[i].x.size()) - 2.0;
    significance += (before.perChain[i] - after.perChain[i]) / std::max(1e-12, after.perChain[i] / dof);
  }
  significance /= static_cast<double>(chains.size());
  const double explained = before.total > 0 ? 1.0 - after.total / before.total : 0.0;
  const double points = static_cast<double>(pointCount(chains));
  fit.rmsBeforePx = std::sqrt(before.total / points);
  fit.rmsAfterPx = std::sqrt(after.total / points);
  if (!(significance >= kMinSignificance) || !(explained >= kMinExplained) || !(shift >= kMinCornerShiftPx)) {
    return std::nullopt;
  }
  return fit;
}

}  // namespace pw::metrology::detect
