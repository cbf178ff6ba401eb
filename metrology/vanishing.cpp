#include "metrology/vanishing.h"

#include <cmath>
#include <string>

#include <opencv2/core.hpp>

namespace pw::metrology {

Result<ImageLine> lineThrough(const glm::dvec2& a, const glm::dvec2& b) {
  const glm::dvec2 d = b - a;
  const double length = glm::length(d);
  if (!(length > 1e-9)) return makeError("the two points of a line coincide");
  const glm::dvec2 n(-d.y / length, d.x / length);
  return ImageLine(n.x, n.y, -glm::dot(n, a));
}

namespace {

// Distance-based consistency of one segment with a vanishing point (homogeneous):
// the line from the segment's midpoint towards the point, and the endpoints' distances
// from it.
double consistencySquared(const Segment& s, const glm::dvec3& vp) {
  const glm::dvec2 mid = 0.5 * (s.from + s.to);
  glm::dvec2 towards = glm::dvec2(vp) - mid * vp.z;  // direction mid -> vp (sign irrelevant)
  const double len = glm::length(towards);
  if (!(len > 1e-12)) return 0.0;
  towards /= len;
  const glm::dvec2 n(-towards.y, towards.x);
  const double d1 = glm::dot(n, s.from - mid), d2 = glm::dot(n, s.to - mid);
  return 0.5 * (d1 * d1 + d2 * d2);
}

}  // namespace

Result<VanishingPoint> fitVanishingPoint(std::span<const Segment> segments) {
  if (segments.size() < 2) return makeError("a vanishing point needs at least two lines");
  // Hartley normalisation: centroid to the origin, mean distance sqrt(2).
  glm::dvec2 centroid(0.0);
  for (const Segment& s : segments) centroid += s.from + s.to;
  centroid /= 2.0 * segments.size();
  double spread = 0;
  for (const Segment& s : segments) spread += glm::length(s.from - centroid) + glm::length(s.to - centroid);
  spread /= 2.0 * segments.size();
  if (!(spread > 1e-9) || !std::isfinite(spread)) return makeError("the lines' points coincide");
  const double scale = std::sqrt(2.0) / spread;

  cv::Mat_<double> a(static_cast<int>(segments.size()), 3);
  for (size_t i = 0; i < segments.size(); ++i) {
    auto line = lineThrough((segments[i].from - centroid) * scale, (segments[i].to - centroid) * scale);
    if (!line) return makeError("a line's two points coincide");
    a(static_cast<int>(i), 0) = line->x;
    a(static_cast<int>(i), 1) = line->y;
    a(static_cast<int>(i), 2) = line->z;
  }
  cv::Mat w, u, vt;
  cv::SVD::compute(a, w, u, vt, cv::SVD::FULL_UV);
  glm::dvec3 xn(vt.at<double>(2, 0), vt.at<double>(2, 1), vt.at<double>(2, 2));
  // Undo the normalisation: x = T^-1 xn with T = [s 0 -s cx; 0 s -s cy; 0 0 1].
  glm::dvec3 x(xn.x / scale + centroid.x * xn.z, xn.y / scale + centroid.y * xn.z, xn.z);
  x = glm::normalize(x);

  VanishingPoint vp;
  const double planar = glm::length(glm::dvec2(xn));
  // Finite when its distance from the centroid, |xn.xy| / |xn.z| in normalised units,
  // is below 1e6 (about a million times the segments' spread).
  vp.finite = std::abs(xn.z) * 1e6 > planar;
  if (vp.finite) {
    if (x.z < 0) x = -x;
    vp.px = glm::dvec2(x) / x.z;
  } else {
    x.z = 0;
    x = glm::normalize(x);
    vp.direction = glm::dvec2(x);
    // Orient along the segments (they are given pointing the same way in 3D).
    double along = 0;
    for (const Segment& s : segments) along += glm::dot(s.to - s.from, vp.direction);
    if (along < 0) {
      vp.direction = -vp.direction;
      x = -x;
    }
  }
  vp.homogeneous = x;
  double sum = 0;
  for (const Segment& s : segments) sum += consistencySquared(s, vp.finite ? glm::dvec3(vp.px, 1.0) : x);
  vp.residualPx = std::sqrt(sum / segments.size());
  return vp;
}

namespace {

Segment edge(const std::array<glm::dvec2, kCornerCount>& c, int from, int to) { return {c[from], c[to]}; }

std::string edgeName(int from, int to) { return std::string(cornerName(from)) + "-" + cornerName(to); }

}  // namespace

Result<CorridorVanishing> corridorVanishing(const std::array<glm::dvec2, kCornerCount>& c) {
  static constexpr int kReceding[4][2] = {{P7, P1}, {P8, P2}, {P5, P3}, {P6, P4}};
  static constexpr int kHorizontal[4][2] = {{P1, P2}, {P3, P4}, {P5, P6}, {P7, P8}};
  static constexpr int kVertical[4][2] = {{P3, P1}, {P4, P2}, {P5, P7}, {P6, P8}};
  auto family = [&](const int (&pairs)[4][2], const char* what) -> Result<VanishingPoint> {
    std::array<Segment, 4> segments;
    for (int i = 0; i < 4; ++i) {
      segments[i] = edge(c, pairs[i][0], pairs[i][1]);
      if (glm::length(segments[i].to - segments[i].from) < 0.5) {
        return makeError("corners " + std::string(cornerName(pairs[i][0])) + " and " + cornerName(pairs[i][1]) +
                         " coincide; the " + what + " edge " + edgeName(pairs[i][0], pairs[i][1]) + " has no length");
      }
    }
    return fitVanishingPoint(segments);
  };
  CorridorVanishing out;
  auto corridor = family(kReceding, "receding");
  if (!corridor) return corridor.error();
  auto horizontal = family(kHorizontal, "horizontal");
  if (!horizontal) return horizontal.error();
  auto vertical = family(kVertical, "vertical");
  if (!vertical) return vertical.error();
  out.corridor = *corridor;
  out.horizontal = *horizontal;
  out.vertical = *vertical;

  if (!out.corridor.finite) {
    return makeError("the receding edges P7-P1, P8-P2, P5-P3, P6-P4 are parallel in the image; the corridor's "
                     "vanishing point is at infinity, so its length cannot be measured");
  }
  // The far corners must lie between the near corners and the vanishing point: the
  // point where the corridor's far end converges. If it lies on the near side, the
  // edges converge towards the viewer, i.e. the vanishing point is behind the camera.
  for (const auto& pair : kReceding) {
    const glm::dvec2 nearPx = c[pair[0]], farPx = c[pair[1]];
    const glm::dvec2 d = farPx - nearPx;
    const double t = glm::dot(out.corridor.px - nearPx, d) / glm::dot(d, d);
    if (t <= 0) {
      return makeError("the receding edges meet behind the camera (the vanishing point lies beyond the near corners); "
                       "check that P1..P4 are the far wall's corners and P5..P8 the near ones");
    }
    if (t < 1) {
      return makeError("the receding edge " + edgeName(pair[0], pair[1]) +
                       " passes its vanishing point before reaching the far wall; check corners " + cornerName(pair[0]) +
                       " and " + cornerName(pair[1]));
    }
  }

  // Horizon: the vanishing line of the floor, through both horizontal vanishing points.
  glm::dvec3 horizon = glm::cross(glm::dvec3(out.corridor.px, 1.0), out.horizontal.homogeneous);
  const double norm = glm::length(glm::dvec2(horizon));
  if (!(norm > 1e-12)) return makeError("the horizontal edges point at the corridor's vanishing point; the corners are degenerate");
  horizon /= norm;
  if (signedDistancePx(horizon, 0.5 * (c[P5] + c[P6])) < 0) horizon = -horizon;
  out.horizon = horizon;
  // Direction along the horizon, left to right (u growing): (-b, a) or its opposite.
  glm::dvec2 along(-horizon.y, horizon.x);
  if (glm::dot(along, c[P4] - c[P3]) + glm::dot(along, c[P6] - c[P5]) < 0) along = -along;
  out.rollDeg = glm::degrees(std::atan2(along.y, along.x));
  return out;
}

}  // namespace pw::metrology
