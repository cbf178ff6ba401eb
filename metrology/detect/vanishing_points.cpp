#include "metrology/detect/vanishing_points.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <random>

#include <opencv2/core.hpp>

#include "metrology/detect/geometry.h"

namespace pw::metrology::detect {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInlierAngleDeg = 1.5;     // on the Gaussian sphere
// The joint fit's segments: within a degree of their direction (the York Urban
// training photos: 46 of 51 within 2 degrees at 1, 45 at 1.5; median 0.74 against 0.85).
constexpr double kJointFitAngleDeg = 1.0;
// An independently fitted direction is kept where it is within this of the orthogonal
// frame's (the detect tests' POV-Ray corridors need 0.25: their independent fits are
// the more precise; York Urban: 46 of 51 within 2 degrees at 0 to 0.5, 44 at 1).
constexpr double kAgreementDeg = 0.25;
constexpr int kFirstDirectionDraws = 250;   // pairs of segments giving the first direction
constexpr size_t kDrawPoolSize = 400;       // the longest segments give and score the hypotheses
constexpr int kRefinementRounds = 3;
constexpr size_t kMinSegments = 8;
// A vanishing point's spread (VanishingPoint::rmsAngleDeg) is measured over the inliers
// this share of the image diagonal or more away from it.
constexpr double kSpreadAwayOfDiagonal = 0.05;

struct SphereSegment {
  glm::dvec3 normal;  // unit normal of the interpretation plane through the camera centre
  double weight;      // length in pixels
};

// The angle between two directions, sign-free, in degrees.
double angleDeg(const glm::dvec3& a, const glm::dvec3& b) {
  return std::acos(std::min(1.0, std::abs(glm::dot(a, b)) / (glm::length(a) * glm::length(b)))) * 180.0 / kPi;
}

glm::dvec3 backProject(glm::dvec2 p, const PinholeCamera& camera) {
  return {(p.x - camera.principalPointPx.x) / camera.focalPx, (p.y - camera.principalPointPx.y) / camera.focalPx, 1.0};
}

// The eigenvector of the smallest eigenvalue of a symmetric 3x3 matrix: the unit
// direction d minimising sum w (n·d)^2, i.e. closest to lying in every plane.
glm::dvec3 leastSquaresDirection(const std::vector<SphereSegment>& segs, const std::vector<int>& members) {
  cv::Matx33d m = cv::Matx33d::zeros();
  for (int i : members) {
    const glm::dvec3& n = segs[i].normal;
    const double w = segs[i].weight;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) m(r, c) += w * n[r] * n[c];
  }
  cv::Matx31d values;
  cv::Matx33d vectors;
  cv::eigen(m, values, vectors);  // descending order
  return glm::normalize(glm::dvec3(vectors(2, 0), vectors(2, 1), vectors(2, 2)));
}

// Labels every segment with the direction whose great circle it lies closest to,
// or -1 when none is within the inlier angle.
void assignLabels(const std::vector<SphereSegment>& segs, const std::array<glm::dvec3, 3>& dirs, std::vector<int>& labels,
                  double tolDeg = kInlierAngleDeg) {
  const double tol = std::sin(tolDeg * kPi / 180.0);
  labels.assign(segs.size(), -1);
  for (size_t i = 0; i < segs.size(); ++i) {
    double best = tol;
    for (int k = 0; k < 3; ++k) {
      const double e = std::abs(glm::dot(segs[i].normal, dirs[k]));
      if (e < best) best = e, labels[i] = k;
    }
  }
}

// Sum over `segs` of each one's truncated-linear support for the nearest of the three
// directions (a segment counts once, for the direction its plane passes closest to).
double frameScore(const std::vector<SphereSegment>& segs, const glm::dvec3& d1, const glm::dvec3& d2, const glm::dvec3& d3,
                  double tol) {
  double score = 0;
  for (const SphereSegment& s : segs) {
    const double e = std::min({std::abs(glm::dot(s.normal, d1)), std::abs(glm::dot(s.normal, d2)), std::abs(glm::dot(s.normal, d3))});
    if (e < tol) score += s.weight * (1.0 - e / tol);
  }
  return score;
}

// For a first direction d1, the best second one on the great circle orthogonal to it,
// searched exhaustively (Lu et al., "2-line exhaustive searching for real-time vanishing
// point estimation in Manhattan world", WACV 2017): every segment not already d1's
// gives the one angle α_i on the circle whose direction lies in its plane; d2 at α and
// d3 at α + 90° are both on the circle, so the score of α is a histogram of the α_i
// folded modulo 90°, each spread over the angles within the inlier tolerance of it.
glm::dvec3 bestSecondDirection(const std::vector<SphereSegment>& segs, const glm::dvec3& d1, double tol) {
  constexpr int kBins = 360;  // 0.25° over the 90° the fold leaves
  constexpr double kBinRad = 0.5 * kPi / kBins;
  const glm::dvec3 a = glm::normalize(glm::cross(d1, std::abs(d1.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
  const glm::dvec3 b = glm::cross(d1, a);
  std::array<double, kBins> histogram{};
  for (const SphereSegment& s : segs) {
    if (std::abs(glm::dot(s.normal, d1)) < tol) continue;
    const double p = glm::dot(s.normal, a), q = glm::dot(s.normal, b), r = std::hypot(p, q);
    if (r < 2 * tol) continue;  // the plane holds most of the circle: no say in where d2 is
    // n · (cos α a + sin α b) = r cos(α - β): zero at α = β + 90°.
    double alpha = std::fmod(std::atan2(q, p) + 0.5 * kPi + 2 * kPi, 0.5 * kPi);
    // Within the tolerance, |n . d| = r |sin(α - α_i)| ~ r |α - α_i| (a few degrees).
    const double slope = r / tol;
    const int centre = static_cast<int>(alpha / kBinRad);
    const int reach = static_cast<int>(1.0 / (slope * kBinRad)) + 1;
    for (int k = -reach; k <= reach; ++k) {
      const double support = 1.0 - slope * std::abs((centre + k + 0.5) * kBinRad - alpha);
      if (support > 0) histogram[(centre + k + kBins) % kBins] += s.weight * support;
    }
  }
  const int peak = static_cast<int>(std::max_element(histogram.begin(), histogram.end()) - histogram.begin());
  // The peak's position to a fraction of a bin, from its neighbours (a parabola).
  const double left = histogram[(peak + kBins - 1) % kBins], mid = histogram[peak], right = histogram[(peak + 1) % kBins];
  const double curvature = left - 2 * mid + right;
  const double offset = curvature < 0 ? std::clamp(0.5 * (left - right) / curvature, -0.5, 0.5) : 0.0;
  const double alpha = (peak + 0.5 + offset) * kBinRad;
  return glm::normalize(std::cos(alpha) * a + std::sin(alpha) * b);
}

// The rotation (columns: the three directions) fitted to the labelled segments by
// Gauss-Newton on the rotation: minimises sum w (n_i · d_label(i))^2 with the three
// directions held orthogonal, so a direction with few segments is fixed by the other two.
std::array<glm::dvec3, 3> jointOrthogonalFit(const std::vector<SphereSegment>& segs, const std::vector<int>& labels,
                                             std::array<glm::dvec3, 3> dirs) {
  for (int iteration = 0; iteration < 10; ++iteration) {
    cv::Matx33d jtj = cv::Matx33d::zeros();
    cv::Vec3d jtr(0, 0, 0);
    for (size_t i = 0; i < segs.size(); ++i) {
      if (labels[i] < 0) continue;
      const glm::dvec3& n = segs[i].normal;
      const glm::dvec3& d = dirs[labels[i]];
      const double r = glm::dot(n, d);
      const glm::dvec3 j = glm::cross(d, n);  // d(n · (ω x d))/dω
      const double w = segs[i].weight;
      for (int p = 0; p < 3; ++p) {
        jtr(p) += w * j[p] * r;
        for (int q = 0; q < 3; ++q) jtj(p, q) += w * j[p] * j[q];
      }
    }
    if (std::abs(cv::determinant(jtj)) < 1e-18) break;
    const cv::Vec3d step = -(jtj.inv() * jtr);
    const glm::dvec3 omega(step(0), step(1), step(2));
    const double angle = glm::length(omega);
    if (angle > 1e-12) {
      const glm::dvec3 axis = omega / angle;
      for (glm::dvec3& d : dirs) {  // Rodrigues
        d = d * std::cos(angle) + glm::cross(axis, d) * std::sin(angle) + axis * glm::dot(axis, d) * (1 - std::cos(angle));
      }
    }
    // Orthonormal again (rounding only).
    dirs[0] = glm::normalize(dirs[0]);
    dirs[1] = glm::normalize(dirs[1] - glm::dot(dirs[1], dirs[0]) * dirs[0]);
    dirs[2] = glm::cross(dirs[0], dirs[1]) * (glm::dot(glm::cross(dirs[0], dirs[1]), dirs[2]) < 0 ? -1.0 : 1.0);
    if (angle < 1e-9) break;
  }
  return dirs;
}


}  // namespace

glm::dvec2 refineFinitePoint(glm::dvec2 v, const std::vector<LineSegment>& segments, const std::vector<int>& members) {
  const auto residual = [&](glm::dvec2 p, const LineSegment& s) {
    const glm::dvec2 m = 0.5 * (s.a + s.b);
    const glm::dvec2 d = p - m;
    const double n = glm::length(d);
    if (n < 1e-9) return 0.0;
    const glm::dvec2 e = s.a - m;
    return (d.x * e.y - d.y * e.x) / n;
  };
  for (int iteration = 0; iteration < 8; ++iteration) {
    cv::Matx22d jtj = cv::Matx22d::zeros();
    cv::Vec2d jtr(0, 0);
    const double h = 1e-3;
    for (int i : members) {
      const LineSegment& s = segments[i];
      const double w = s.lengthPx;
      const double r = residual(v, s);
      const double jx = (residual(v + glm::dvec2(h, 0), s) - r) / h;
      const double jy = (residual(v + glm::dvec2(0, h), s) - r) / h;
      jtj(0, 0) += w * jx * jx, jtj(0, 1) += w * jx * jy, jtj(1, 1) += w * jy * jy;
      jtr(0) += w * jx * r, jtr(1) += w * jy * r;
    }
    jtj(1, 0) = jtj(0, 1);
    if (cv::determinant(jtj) <= 1e-12) break;
    const cv::Vec2d step = jtj.inv() * jtr;
    v -= glm::dvec2(step(0), step(1));
    if (std::hypot(step(0), step(1)) < 1e-4) break;
  }
  return v;
}

namespace {

// RMS angle (degrees) between inlier segments and the lines from their midpoints
// to the vanishing point, length-weighted, over the inliers whose midpoints lie
// kSpreadAwayOfDiagonal of the image diagonal or more from a finite point (all of them
// where none does). Near the point a segment's line to it is ill-defined: a short edge
// a few dozen pixels from it, on the sphere within kInlierAngleDeg, is 10-40 degrees
// off in the image. Measured over every inlier, the random TUNE scenes 0-599 had 103 of
// 600 corridor points "scattered" (over 3 degrees) while every one of them lay within
// a degree of the truth (median 0.09); away from the point, 9.
double rmsAngleDeg(glm::dvec3 point, const std::vector<LineSegment>& segments, const std::vector<int>& members,
                   double awayPx) {
  const bool finite = std::abs(point.z) > 1e-9;
  const glm::dvec2 at = finite ? glm::dvec2(point) / point.z : glm::dvec2(0);
  const auto away = [&](const LineSegment& s) { return !finite || glm::length(0.5 * (s.a + s.b) - at) >= awayPx; };
  const bool anyAway = std::any_of(members.begin(), members.end(), [&](int i) { return away(segments[i]); });
  double sum = 0, weight = 0;
  for (int i : members) {
    const LineSegment& s = segments[i];
    if (anyAway && !away(s)) continue;
    const glm::dvec2 m = 0.5 * (s.a + s.b);
    const glm::dvec2 toPoint = directionTowards(point, m);
    const glm::dvec2 along = (s.b - s.a) / s.lengthPx;
    const double sine = std::abs(toPoint.x * along.y - toPoint.y * along.x);
    const double angle = std::asin(std::min(1.0, sine));
    sum += s.lengthPx * angle * angle;
    weight += s.lengthPx;
  }
  return weight > 0 ? std::sqrt(sum / weight) * 180.0 / kPi : 0.0;
}

// Share of 8 angular sectors around the (finite) point holding inlier segments of
// at least 2% of the image diagonal: a corridor's lines arrive from all around.
double sectorCoverage(glm::dvec2 v, const std::vector<LineSegment>& segments, const std::vector<int>& members,
                      double diagonal) {
  std::array<double, 8> lengthPerSector{};
  for (int i : members) {
    const glm::dvec2 m = 0.5 * (segments[i].a + segments[i].b) - v;
    const double angle = wrapAngle(std::atan2(m.y, m.x));
    lengthPerSector[std::min(7, static_cast<int>(angle / (2 * kPi) * 8))] += segments[i].lengthPx;
  }
  int covered = 0;
  for (double l : lengthPerSector) covered += l >= 0.02 * diagonal;
  return covered / 8.0;
}

}  // namespace

Result<ManhattanFrame> estimateManhattanFrame(const std::vector<LineSegment>& segments, const PinholeCamera& camera,
                                              cv::Size imageSize, FrameRefinement refinement) {
  if (segments.size() < kMinSegments) {
    return makeError("only " + std::to_string(segments.size()) + " straight edges in the photo");
  }
  const double diagonal = std::hypot(imageSize.width, imageSize.height);
  std::vector<SphereSegment> sphere;
  sphere.reserve(segments.size());
  for (const LineSegment& s : segments) {
    glm::dvec3 n = glm::cross(backProject(s.a, camera), backProject(s.b, camera));
    sphere.push_back({glm::normalize(n), s.lengthPx});
  }

  // Hypotheses: the first direction from two of the longest segments, drawn in
  // proportion to length; the second searched exhaustively around the great circle
  // orthogonal to it (bestSecondDirection), the third their cross product; scored by
  // the same longest segments (a bounded cost on a large photo: the York Urban photos
  // score the same with all of them), refined below with all.
  std::vector<int> pool(segments.size());
  std::iota(pool.begin(), pool.end(), 0);
  std::sort(pool.begin(), pool.end(), [&](int a, int b) { return segments[a].lengthPx > segments[b].lengthPx; });
  pool.resize(std::min(pool.size(), kDrawPoolSize));
  std::vector<double> poolWeights;
  for (int i : pool) poolWeights.push_back(segments[i].lengthPx);
  std::mt19937 rng(12345);  // fixed seed: the same photo always gives the same answer
  std::discrete_distribution<int> draw(poolWeights.begin(), poolWeights.end());

  const double tol = std::sin(kInlierAngleDeg * kPi / 180.0);
  std::vector<SphereSegment> scoring;
  for (int i : pool) scoring.push_back(sphere[i]);
  std::array<glm::dvec3, 3> best{};
  double bestScore = -1;
  for (int it = 0; it < kFirstDirectionDraws; ++it) {
    const int a = pool[draw(rng)], b = pool[draw(rng)];
    if (a == b) continue;
    glm::dvec3 d1 = glm::cross(sphere[a].normal, sphere[b].normal);
    if (glm::length(d1) < 1e-6) continue;
    d1 = glm::normalize(d1);
    const glm::dvec3 d2 = bestSecondDirection(scoring, d1, tol);
    const glm::dvec3 d3 = glm::cross(d1, d2);
    const double score = frameScore(scoring, d1, d2, d3, tol);
    if (score > bestScore) bestScore = score, best = {d1, d2, d3};
  }
  if (bestScore <= 0) return makeError("no three orthogonal directions among the straight edges");

  // Refine: label, fit, label again. With the focal length known the three directions
  // are one rotation, fitted to all the labelled segments at once; with a guess, each
  // direction alone, so that the guess biases the labels only, not the points.
  std::vector<int> labels;
  std::array<glm::dvec3, 3> dirs = best;
  for (int round = 0; round < kRefinementRounds; ++round) {
    assignLabels(sphere, dirs, labels);
    for (int k = 0; k < 3; ++k) {
      std::vector<int> members;
      for (size_t i = 0; i < labels.size(); ++i)
        if (labels[i] == k) members.push_back(static_cast<int>(i));
      if (members.size() >= 2) dirs[k] = leastSquaresDirection(sphere, members);
    }
  }
  // With the focal length known: the rotation fitted to all three families at once,
  // and each direction the independent fit's where the two agree to within
  // kAgreementDeg (strong families: the orthogonal frame's small bias from a principal
  // point or lens slightly off stays out of them), the orthogonal frame's where they do
  // not (a weak or contaminated family, fixed by the other two).
  const bool joint = refinement == FrameRefinement::kJointOrthogonal;
  std::array<bool, 3> fromJoint{false, false, false};
  std::array<glm::dvec3, 3> orthogonal = best;
  if (joint) {
    std::vector<int> jointLabels;
    for (int round = 0; round < kRefinementRounds; ++round) {
      assignLabels(sphere, orthogonal, jointLabels, kJointFitAngleDeg);
      orthogonal = jointOrthogonalFit(sphere, jointLabels, orthogonal);
    }
    for (int k = 0; k < 3; ++k) {
      if (angleDeg(dirs[k], orthogonal[k]) > kAgreementDeg) dirs[k] = orthogonal[k], fromJoint[k] = true;
    }
  }
  assignLabels(sphere, dirs, labels);

  // Corridor: the direction most nearly along the optical axis; vertical: the one
  // most nearly along the image's v axis of the other two.
  std::array<int, 3> order{0, 1, 2};
  const int corridor = static_cast<int>(std::max_element(dirs.begin(), dirs.end(), [](auto& x, auto& y) {
                                          return std::abs(x.z) < std::abs(y.z);
                                        }) - dirs.begin());
  int vertical = -1, horizontal = -1;
  for (int k : order) {
    if (k == corridor) continue;
    if (vertical < 0 || std::abs(dirs[k].y) > std::abs(dirs[vertical].y)) vertical = k;
  }
  for (int k : order)
    if (k != corridor && k != vertical) horizontal = k;

  ManhattanFrame frame;
  frame.labels.assign(labels.size(), -1);
  const std::array<int, 3> roleOf = {corridor, horizontal, vertical};
  for (size_t i = 0; i < labels.size(); ++i) {
    for (int role = 0; role < 3; ++role)
      if (labels[i] == roleOf[role]) frame.labels[i] = role;
  }
  const glm::dmat3 k(camera.focalPx, 0, 0, 0, camera.focalPx, 0, camera.principalPointPx.x, camera.principalPointPx.y, 1);
  std::array<VanishingPoint*, 3> out = {&frame.corridor, &frame.horizontal, &frame.vertical};
  for (int role = 0; role < 3; ++role) {
    VanishingPoint& vp = *out[role];
    std::vector<int> members;
    for (size_t i = 0; i < frame.labels.size(); ++i)
      if (frame.labels[i] == role) members.push_back(static_cast<int>(i));
    glm::dvec3 p = k * dirs[roleOf[role]];
    // A direction nearly parallel to the image plane vanishes far outside the photo:
    // keep it as a point at infinity rather than at an unstable finite position.
    if (std::abs(p.z) * 1e3 * diagonal < std::hypot(p.x, p.y)) p.z = 0;
    if (!fromJoint[roleOf[role]] && std::abs(p.z) > 1e-12 && role == 0 && members.size() >= 2) {
      const glm::dvec2 refined = refineFinitePoint(dehomogenize(p), segments, members);
      // Refined in the image, the point must still agree with the orthogonal frame.
      if (!joint || angleDeg(backProject(refined, camera), orthogonal[roleOf[role]]) <= kAgreementDeg) {
        p = homogeneous(refined);
      } else {
        p = k * orthogonal[roleOf[role]];
      }
    }
    vp.point = glm::normalize(p);
    vp.inlierCount = static_cast<int>(members.size());
    for (int i : members) vp.inlierLengthPx += segments[i].lengthPx;
    vp.rmsAngleDeg = rmsAngleDeg(vp.point, segments, members, kSpreadAwayOfDiagonal * diagonal);
    const double support = 1.0 - std::exp(-vp.inlierLengthPx / diagonal);
    if (role == 0) {
      vp.confidence = vp.isFinite() ? sectorCoverage(vp.pixel(), segments, members, diagonal) * support : 0.0;
    } else {
      vp.confidence = 1.0 - std::exp(-2.0 * vp.inlierLengthPx / diagonal);
    }
  }
  if (!frame.corridor.isFinite()) return makeError("no vanishing point along the view direction");
  return frame;
}

std::optional<double> focalFromOrthogonalPoints(const VanishingPoint& v1, const VanishingPoint& v2,
                                                glm::dvec2 principalPointPx, double imageDiagonalPx) {
  // Points farther out than this make f^2 the small difference of large numbers.
  const double maxDistance = 20.0 * imageDiagonalPx;
  if (!isNear(v1.point, principalPointPx, maxDistance) || !isNear(v2.point, principalPointPx, maxDistance)) {
    return std::nullopt;
  }
  const double f2 = -glm::dot(v1.pixel() - principalPointPx, v2.pixel() - principalPointPx);
  if (!(f2 > 0)) return std::nullopt;
  return std::sqrt(f2);
}

}  // namespace pw::metrology::detect
