#include "bench/lu_manhattan.h"

#include <algorithm>
#include <cmath>
#include <random>

#include <opencv2/imgproc.hpp>

namespace pw::bench::lu {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
constexpr int kLatitudeBins = 90;    // 1 degree, the half sphere z > 0
constexpr int kLongitudeBins = 360;  // 1 degree
constexpr int kSecondSteps = 360;    // v2 around the great circle orthogonal to v1
constexpr double kNoiseRatio = 0.5;
constexpr double kConfidence = 0.9999;
constexpr double kMaxPairAngle = 60.0 * kDeg;

struct LineInfo {
  glm::dvec3 line;     // homogeneous image line through the end points
  double lengthPx;
  double orientation;  // [0, π)
};

// What does not depend on the focal length: the lines, every pair's intersection with
// its weight, and the first directions' image points from the random pairs.
struct Prepared {
  std::vector<std::pair<glm::dvec3, double>> intersections;  // homogeneous pixel, weight
  std::vector<glm::dvec3> firstPoints;                       // homogeneous pixel, z != 0
};

Prepared prepare(const std::vector<Line>& lines) {
  Prepared p;
  std::vector<LineInfo> info;
  info.reserve(lines.size());
  for (const Line& l : lines) {
    double orientation = std::atan2(l.a.y - l.b.y, l.a.x - l.b.x);
    if (orientation < 0) orientation += kPi;
    info.push_back({glm::cross(glm::dvec3(l.a, 1.0), glm::dvec3(l.b, 1.0)), l.lengthPx, orientation});
  }
  const size_t n = info.size();
  for (size_t i = 0; i + 1 < n; ++i) {
    for (size_t j = i + 1; j < n; ++j) {
      const glm::dvec3 x = glm::cross(info[i].line, info[j].line);
      if (x.z == 0) continue;
      double dev = std::abs(info[i].orientation - info[j].orientation);
      dev = std::min(kPi - dev, dev);
      if (dev > kMaxPairAngle) continue;
      p.intersections.push_back({x, std::sqrt(info[i].lengthPx * info[j].lengthPx) * (std::sin(2.0 * dev) + 0.2)});
    }
  }
  if (n < 2) return p;
  // RANSAC's number of draws: a draw is good when both lines are inliers of the same
  // one of the three directions.
  const double good = std::pow(1.0 - kNoiseRatio, 2) / 3.0;
  const int draws = static_cast<int>(std::log(1.0 - kConfidence) / std::log(1.0 - good));
  std::mt19937 rng(20170324);
  std::uniform_int_distribution<size_t> pick(0, n - 1);
  for (int attempt = 0; static_cast<int>(p.firstPoints.size()) < draws && attempt < 100 * draws; ++attempt) {
    const size_t a = pick(rng), b = pick(rng);
    if (a == b) continue;
    const glm::dvec3 v = glm::cross(info[a].line, info[b].line);
    if (v.z == 0) continue;
    p.firstPoints.push_back(v);
  }
  return p;
}

// The unit direction of a homogeneous pixel, in front of the camera (z >= 0).
glm::dvec3 direction(glm::dvec3 x, double f, glm::dvec2 pp) {
  glm::dvec3 d(x.x - pp.x * x.z, x.y - pp.y * x.z, f * x.z);
  const double n = glm::length(d);
  if (!(n > 0)) return {0, 0, 1};
  d /= n;
  return d.z < 0 ? -d : d;
}

int binOf(const glm::dvec3& d) {
  const double latitude = std::acos(std::clamp(d.z, -1.0, 1.0));
  const double longitude = std::atan2(d.x, d.y) + kPi;
  const int la = std::clamp(static_cast<int>(latitude / kDeg), 0, kLatitudeBins - 1);
  const int lo = std::clamp(static_cast<int>(longitude / kDeg), 0, kLongitudeBins - 1);
  return la * kLongitudeBins + lo;
}

Frame frameAt(const Prepared& p, double f, glm::dvec2 pp) {
  Frame best;
  if (p.firstPoints.empty()) return best;
  std::vector<double> grid(kLatitudeBins * kLongitudeBins, 0.0);
  for (const auto& [x, w] : p.intersections) grid[binOf(direction(x, f, pp))] += w;
  // Each bin plus its 3x3 neighbourhood's mean (longitude wraps, latitude clamps).
  std::vector<double> smooth(grid.size());
  for (int la = 0; la < kLatitudeBins; ++la) {
    for (int lo = 0; lo < kLongitudeBins; ++lo) {
      double sum = 0;
      for (int dla = -1; dla <= 1; ++dla) {
        const int r = std::clamp(la + dla, 0, kLatitudeBins - 1);
        for (int dlo = -1; dlo <= 1; ++dlo) sum += grid[r * kLongitudeBins + (lo + dlo + kLongitudeBins) % kLongitudeBins];
      }
      smooth[la * kLongitudeBins + lo] = grid[la * kLongitudeBins + lo] + sum / 9.0;
    }
  }
  const double step = 2.0 * kPi / kSecondSteps;
  for (const glm::dvec3& x : p.firstPoints) {
    const glm::dvec3 v1 = direction(x, f, pp);
    const double s1 = smooth[binOf(v1)];
    for (int j = 0; j < kSecondSteps; ++j) {
      // v2 = (sin φ sin λ, sin φ cos λ, cos φ) with v1 · v2 = 0.
      const double lambda = j * step;
      const double k1 = v1.x * std::sin(lambda) + v1.y * std::cos(lambda);
      const double phi = std::atan2(-v1.z, k1);
      glm::dvec3 v2(std::sin(phi) * std::sin(lambda), std::sin(phi) * std::cos(lambda), std::cos(phi));
      v2 = glm::normalize(v2);
      if (v2.z < 0) v2 = -v2;
      glm::dvec3 v3 = glm::cross(v1, v2);
      const double n3 = glm::length(v3);
      if (!(n3 > 1e-12)) continue;
      v3 /= n3;
      if (v3.z < 0) v3 = -v3;
      const double score = s1 + smooth[binOf(v2)] + smooth[binOf(v3)];
      if (score > best.score) best = {true, {v1, v2, v3}, score};
    }
  }
  return best;
}

}  // namespace

std::vector<Line> detectLines(const cv::Mat& gray, double minLengthPx) {
  cv::Ptr<cv::LineSegmentDetector> lsd = cv::createLineSegmentDetector(cv::LSD_REFINE_STD);
  std::vector<cv::Vec4f> raw;
  lsd->detect(gray, raw);
  std::vector<Line> lines;
  for (const cv::Vec4f& r : raw) {
    Line l{{r[0], r[1]}, {r[2], r[3]}, 0};
    l.lengthPx = glm::length(l.b - l.a);
    if (l.lengthPx > minLengthPx) lines.push_back(l);
  }
  return lines;
}

Frame estimateFrame(const std::vector<Line>& lines, double focalPx, glm::dvec2 principalPointPx) {
  return frameAt(prepare(lines), focalPx, principalPointPx);
}

FocalSearch estimateFrameAndFocal(const std::vector<Line>& lines, glm::dvec2 principalPointPx, cv::Size imageSize) {
  const Prepared p = prepare(lines);
  const double longSide = std::max(imageSize.width, imageSize.height);
  const double diagonal = std::hypot(imageSize.width, imageSize.height);
  FocalSearch result{longSide, frameAt(p, longSide, principalPointPx)};
  for (int iteration = 0; iteration < 8 && result.frame.found; ++iteration) {
    // The frame's points are orthogonal for the f they were found with, so f is read
    // off the points fitted to each one's lines alone: the lines within 6 degrees of
    // pointing at it (the authors' clustering), their least-squares intersection.
    const glm::dmat3 k(result.focalPx, 0, 0, 0, result.focalPx, 0, principalPointPx.x, principalPointPx.y, 1);
    std::array<glm::dvec3, 3> points;
    std::array<cv::Matx33d, 3> normal;
    normal.fill(cv::Matx33d::zeros());
    std::array<int, 3> members{};
    for (int j = 0; j < 3; ++j) points[j] = k * result.frame.directions[j];
    for (const Line& l : lines) {
      const glm::dvec2 m = 0.5 * (l.a + l.b), along = (l.b - l.a) / l.lengthPx;
      int best = -1;
      double bestAngle = 6.0 * kDeg;
      for (int j = 0; j < 3; ++j) {
        glm::dvec2 to(points[j].x - m.x * points[j].z, points[j].y - m.y * points[j].z);
        if (glm::length(to) == 0) continue;
        to = glm::normalize(to);
        const double angle = std::asin(std::min(1.0, std::abs(along.x * to.y - along.y * to.x)));
        if (angle < bestAngle) bestAngle = angle, best = j;
      }
      if (best < 0) continue;
      glm::dvec3 line = glm::cross(glm::dvec3(l.a, 1.0), glm::dvec3(l.b, 1.0));
      line /= std::hypot(line.x, line.y);
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) normal[best](r, c) += l.lengthPx * line[r] * line[c];
      ++members[best];
    }
    // Finite points (within 20 image diagonals) fitted to two lines or more.
    std::vector<glm::dvec2> finite;
    for (int j = 0; j < 3; ++j) {
      if (members[j] < 2) continue;
      cv::Matx31d values;
      cv::Matx33d vectors;
      cv::eigen(normal[j], values, vectors);
      const glm::dvec3 v(vectors(2, 0), vectors(2, 1), vectors(2, 2));
      if (std::abs(v.z) < 1e-12) continue;
      const glm::dvec2 px(v.x / v.z, v.y / v.z);
      if (glm::length(px - principalPointPx) <= 20.0 * diagonal) finite.push_back(px);
    }
    // f^2 = -(v1 - c).(v2 - c) from the two nearest the principal point.
    std::sort(finite.begin(), finite.end(), [&](glm::dvec2 a, glm::dvec2 b) {
      return glm::length(a - principalPointPx) < glm::length(b - principalPointPx);
    });
    if (finite.size() < 2) break;
    const double f2 = -glm::dot(finite[0] - principalPointPx, finite[1] - principalPointPx);
    if (!(f2 > 0)) break;
    const double f = std::sqrt(f2);
    if (!(f > 0.3 * longSide && f < 5.0 * longSide)) break;
    const bool settled = std::abs(f - result.focalPx) <= 0.005 * f;
    result = {f, frameAt(p, f, principalPointPx)};
    if (settled) break;
  }
  return result;
}

}  // namespace pw::bench::lu
