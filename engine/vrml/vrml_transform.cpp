#include "engine/vrml/vrml_transform.h"

#include <algorithm>
#include <cmath>

namespace pw::engine::vrml {

glm::dmat3 rotationMatrix(const glm::dvec4& r) {
  const glm::dvec3 axis(r.x, r.y, r.z);
  const double length = glm::length(axis);
  if (!(length > 0.0) || r.w == 0.0) return glm::dmat3(1.0);
  const glm::dvec3 a = axis / length;
  const double c = std::cos(r.w), s = std::sin(r.w), t = 1.0 - c;
  // Rodrigues' formula, column-major.
  return glm::dmat3(t * a.x * a.x + c, t * a.x * a.y + s * a.z, t * a.x * a.z - s * a.y,  // column 0
                    t * a.x * a.y - s * a.z, t * a.y * a.y + c, t * a.y * a.z + s * a.x,  // column 1
                    t * a.x * a.z + s * a.y, t * a.y * a.z - s * a.x, t * a.z * a.z + c);  // column 2
}

glm::dvec4 axisAngle(const glm::dmat3& m) {
  const double trace = m[0][0] + m[1][1] + m[2][2];
  const double cosAngle = std::clamp((trace - 1.0) * 0.5, -1.0, 1.0);
  // Skew part: m - m^T = 2 sin(angle) [axis]x
  glm::dvec3 axis(m[1][2] - m[2][1], m[2][0] - m[0][2], m[0][1] - m[1][0]);
  const double sinTimes2 = glm::length(axis);
  if (sinTimes2 < 1e-12 && cosAngle > 0.0) return {0.0, 0.0, 1.0, 0.0};
  double angle = std::atan2(sinTimes2 * 0.5, cosAngle);
  if (sinTimes2 < 1e-6 && cosAngle < 0.0) {
    // Near 180 degrees the skew part vanishes; take the axis from the symmetric part:
    // m + I = 2 a a^T (for angle pi), using its largest column.
    const glm::dmat3 s = m + glm::dmat3(1.0);
    int best = 0;
    for (int i = 1; i < 3; ++i) {
      if (s[i][i] > s[best][best]) best = i;
    }
    axis = s[best];
    const double length = glm::length(axis);
    if (!(length > 0.0)) return {0.0, 0.0, 1.0, 0.0};
    axis /= length;
    // Keep the sign consistent with the (small) skew part when there is one.
    const glm::dvec3 skew(m[1][2] - m[2][1], m[2][0] - m[0][2], m[0][1] - m[1][0]);
    if (glm::dot(skew, axis) < 0.0) axis = -axis;
    return {axis.x, axis.y, axis.z, angle};
  }
  axis /= sinTimes2;
  return {axis.x, axis.y, axis.z, angle};
}

namespace {

glm::dmat4 translationMatrix(const glm::dvec3& t) {
  glm::dmat4 m(1.0);
  m[3] = glm::dvec4(t, 1.0);
  return m;
}

glm::dmat4 extend(const glm::dmat3& m) { return glm::dmat4(m); }

// Eigen-decomposition of a symmetric 3x3 matrix by cyclic Jacobi rotations: returns
// V (columns are eigenvectors) and the eigenvalues. A diagonal input is returned
// untouched, so axis-aligned scales give V = identity.
void jacobiEigen(glm::dmat3 a, glm::dmat3& v, glm::dvec3& values) {
  v = glm::dmat3(1.0);
  for (int sweep = 0; sweep < 50; ++sweep) {
    const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    const double diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
    if (off <= 1e-300 || off <= diag * 1e-34) break;
    for (int p = 0; p < 2; ++p) {
      for (int q = p + 1; q < 3; ++q) {
        if (a[p][q] == 0.0) continue;
        const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
        const double t = (theta >= 0 ? 1.0 : -1.0) / (std::fabs(theta) + std::sqrt(theta * theta + 1.0));
        const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
        glm::dmat3 j(1.0);
        j[p][p] = c;
        j[q][q] = c;
        j[q][p] = s;   // column q, row p
        j[p][q] = -s;  // column p, row q
        a = glm::transpose(j) * a * j;
        v = v * j;
      }
    }
  }
  values = {a[0][0], a[1][1], a[2][2]};
}

}  // namespace

glm::dmat4 composeTransform(const TransformFields& f) {
  const glm::dmat3 r = rotationMatrix(f.rotation);
  const glm::dmat3 sr = rotationMatrix(f.scaleOrientation);
  const glm::dmat3 s(glm::dvec3(f.scale.x, 0, 0), glm::dvec3(0, f.scale.y, 0), glm::dvec3(0, 0, f.scale.z));
  const glm::dmat3 linear = r * sr * s * glm::transpose(sr);
  return translationMatrix(f.translation) * translationMatrix(f.center) * extend(linear) *
         translationMatrix(-f.center);
}

TransformFields decomposeTransform(const glm::dmat4& m) {
  TransformFields f;
  f.translation = glm::dvec3(m[3]);
  const glm::dmat3 a(m);
  glm::dmat3 v;
  glm::dvec3 lambda;
  jacobiEigen(glm::transpose(a) * a, v, lambda);
  glm::dvec3 sigma(std::sqrt(std::max(lambda.x, 0.0)), std::sqrt(std::max(lambda.y, 0.0)),
                   std::sqrt(std::max(lambda.z, 0.0)));
  const double largest = std::max({sigma.x, sigma.y, sigma.z});
  if (!(largest > 0.0)) {
    f.scale = glm::dvec3(0.0);
    return f;
  }
  if (glm::determinant(v) < 0.0) v[2] = -v[2];
  // U's columns: A v_i / sigma_i; a vanishing scale gets a column completing the basis.
  glm::dmat3 u;
  for (int i = 0; i < 3; ++i) u[i] = sigma[i] > largest * 1e-12 ? a * v[i] / sigma[i] : glm::dvec3(0.0);
  for (int i = 0; i < 3; ++i) {
    if (u[i] != glm::dvec3(0.0)) continue;
    const glm::dvec3 p = u[(i + 1) % 3], q = u[(i + 2) % 3];
    glm::dvec3 c = glm::cross(p, q);
    if (glm::length(c) < 0.5) {
      // Two vanishing scales: any direction orthogonal to the remaining one.
      const glm::dvec3 known = p != glm::dvec3(0.0) ? p : q != glm::dvec3(0.0) ? q : glm::dvec3(1, 0, 0);
      c = glm::normalize(glm::cross(known, std::fabs(known.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
    }
    u[i] = glm::normalize(c);
  }
  if (glm::determinant(u) < 0.0) {
    // A mirror: carry it as a negative scale on the third axis.
    u[2] = -u[2];
    sigma.z = -sigma.z;
  }
  const glm::dmat3 rotation = u * glm::transpose(v);
  f.rotation = axisAngle(rotation);
  f.scale = sigma;
  f.scaleOrientation = axisAngle(v);
  // Uniform scale needs no orientation; keep the output clean.
  if (std::fabs(sigma.x - sigma.y) <= 1e-12 * largest && std::fabs(sigma.y - sigma.z) <= 1e-12 * largest &&
      sigma.z > 0) {
    f.scaleOrientation = {0.0, 0.0, 1.0, 0.0};
    f.rotation = axisAngle(a / sigma.x);
    f.scale = glm::dvec3(sigma.x);
  }
  return f;
}

glm::mat4 toFloatMatrix(const glm::dmat4& m) {
  double largest = 0.0;
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) largest = std::max(largest, std::fabs(m[c][r]));
  }
  glm::mat4 out(m);
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) {
      if (std::fabs(m[c][r]) < largest * 1e-12) out[c][r] = 0.0f;
    }
  }
  return out;
}

glm::dmat3 rotationPart(const glm::dmat4& m) {
  const TransformFields f = decomposeTransform(m);
  return rotationMatrix(f.rotation);
}

}  // namespace pw::engine::vrml
