// Small projective-geometry helpers for detection: points and lines in homogeneous
// image coordinates (pixels; origin at the centre of the top-left pixel, v down).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>

#include <glm/glm.hpp>

namespace pw::metrology::detect {

inline glm::dvec3 homogeneous(glm::dvec2 p) { return {p.x, p.y, 1.0}; }

// The line through two homogeneous points, scaled so that (a, b) is a unit normal:
// l·(u, v, 1) is then the signed distance in pixels.
inline glm::dvec3 normalizedLine(glm::dvec3 line) {
  const double n = std::hypot(line.x, line.y);
  return n > 0 ? line / n : line;
}
// The z of the 3D cross product: |a||b| sin(angle from a to b).
inline double cross2(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }
inline glm::dvec3 lineThrough(glm::dvec3 a, glm::dvec3 b) { return normalizedLine(glm::cross(a, b)); }
inline glm::dvec3 lineThrough(glm::dvec2 a, glm::dvec2 b) { return lineThrough(homogeneous(a), homogeneous(b)); }

// Intersection of two lines; nullopt when they are parallel (meet at infinity).
inline std::optional<glm::dvec2> intersect(glm::dvec3 l1, glm::dvec3 l2) {
  const glm::dvec3 p = glm::cross(l1, l2);
  if (std::abs(p.z) < 1e-12 * (std::abs(p.x) + std::abs(p.y))) return std::nullopt;
  if (p.x == 0 && p.y == 0 && p.z == 0) return std::nullopt;
  return glm::dvec2(p.x / p.z, p.y / p.z);
}

// A vanishing point is a homogeneous point that may lie at infinity (z = 0). These
// say where it is seen from an image point: the unit direction towards it (for a
// point at infinity, the direction it names, sign chosen to point along `hint`).
inline glm::dvec2 directionTowards(glm::dvec3 vanishingPoint, glm::dvec2 from, glm::dvec2 hint = {1, 0}) {
  glm::dvec2 d;
  const double w = vanishingPoint.z;
  const double scale = std::hypot(vanishingPoint.x, vanishingPoint.y);
  if (std::abs(w) > 1e-9 * scale) {
    d = glm::dvec2(vanishingPoint.x / w, vanishingPoint.y / w) - from;
  } else {
    d = glm::dvec2(vanishingPoint.x, vanishingPoint.y);
  }
  const double n = glm::length(d);
  if (n == 0) return hint;
  d /= n;
  return glm::dot(d, hint) < 0 ? -d : d;
}

// True when the homogeneous point is at a finite image position no farther than
// `maxDistancePx` from `centre`.
inline bool isNear(glm::dvec3 point, glm::dvec2 centre, double maxDistancePx) {
  if (std::abs(point.z) < 1e-12) return false;
  const glm::dvec2 p(point.x / point.z, point.y / point.z);
  return glm::length(p - centre) <= maxDistancePx;
}

inline glm::dvec2 dehomogenize(glm::dvec3 p) { return {p.x / p.z, p.y / p.z}; }

// Wraps an angle to [0, 2π).
inline double wrapAngle(double a) {
  constexpr double kTwoPi = 6.283185307179586;
  a = std::fmod(a, kTwoPi);
  return a < 0 ? a + kTwoPi : a;
}

// Calls f(choice) for every choice of one index per slot (index i in [0, counts[i])),
// the last slot changing fastest, as nested loops over the slots in order would.
template <std::size_t N, class F>
void forEachChoice(const std::array<int, N>& counts, F&& f) {
  for (int n : counts)
    if (n <= 0) return;
  std::array<int, N> choice{};
  for (;;) {
    f(static_cast<const std::array<int, N>&>(choice));
    std::size_t i = N;
    while (i > 0 && ++choice[i - 1] == counts[i - 1]) choice[--i] = 0;
    if (i == 0) return;
  }
}

}  // namespace pw::metrology::detect
