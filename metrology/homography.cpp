#include "metrology/homography.h"

#include <cmath>

#include <opencv2/core.hpp>

namespace pw::metrology {

namespace {

// Similarity taking the points' centroid to 0 and their mean distance to sqrt(2).
cv::Matx33d normalising(const std::array<glm::dvec2, 4>& p) {
  const glm::dvec2 c = 0.25 * (p[0] + p[1] + p[2] + p[3]);
  double spread = 0;
  for (const auto& q : p) spread += glm::length(q - c);
  spread /= 4;
  const double s = spread > 0 ? std::sqrt(2.0) / spread : 1.0;
  return {s, 0, -s * c.x, 0, s, -s * c.y, 0, 0, 1};
}

}  // namespace

glm::dvec2 applyHomography(const cv::Matx33d& h, const glm::dvec2& p) {
  const double w = h(2, 0) * p.x + h(2, 1) * p.y + h(2, 2);
  return {(h(0, 0) * p.x + h(0, 1) * p.y + h(0, 2)) / w, (h(1, 0) * p.x + h(1, 1) * p.y + h(1, 2)) / w};
}

glm::dmat2 homographyJacobian(const cv::Matx33d& h, const glm::dvec2& p) {
  const double w = h(2, 0) * p.x + h(2, 1) * p.y + h(2, 2);
  const glm::dvec2 q = applyHomography(h, p);
  // d(u)/dx = (h00 - u h20) / w, and so on (quotient rule).
  return glm::dmat2((h(0, 0) - q.x * h(2, 0)) / w, (h(1, 0) - q.y * h(2, 0)) / w,  // column 0: d/dx
                    (h(0, 1) - q.x * h(2, 1)) / w, (h(1, 1) - q.y * h(2, 1)) / w);  // column 1: d/dy
}

double largestStretch(const glm::dmat2& j) {
  // Singular values of a 2x2 matrix from its Frobenius norm and determinant.
  const double f = j[0][0] * j[0][0] + j[0][1] * j[0][1] + j[1][0] * j[1][0] + j[1][1] * j[1][1];
  const double d = j[0][0] * j[1][1] - j[1][0] * j[0][1];
  return std::sqrt(0.5 * (f + std::sqrt(std::max(0.0, f * f - 4 * d * d))));
}

Result<cv::Matx33d> homographyFromCorners(const std::array<glm::dvec2, 4>& src, const std::array<glm::dvec2, 4>& dst) {
  for (const auto* set : {&src, &dst}) {
    for (const auto& p : *set) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) return makeError("a corner of the homography is not finite");
    }
  }
  const cv::Matx33d ts = normalising(src), td = normalising(dst);
  // The seed paper's system: for each correspondence (x, y) -> (P, Q),
  //   x a11 + y a12 + a13 - x P a31 - y P a32 = P
  //   x a21 + y a22 + a23 - x Q a31 - y Q a32 = Q
  cv::Matx<double, 8, 8> a;
  cv::Matx<double, 8, 1> b;
  for (int i = 0; i < 4; ++i) {
    const cv::Vec3d s = ts * cv::Vec3d(src[i].x, src[i].y, 1.0), d = td * cv::Vec3d(dst[i].x, dst[i].y, 1.0);
    const double x = s[0], y = s[1], p = d[0], q = d[1];
    const double rowP[8] = {x, y, 1, 0, 0, 0, -x * p, -y * p};
    const double rowQ[8] = {0, 0, 0, x, y, 1, -x * q, -y * q};
    for (int k = 0; k < 8; ++k) {
      a(2 * i, k) = rowP[k];
      a(2 * i + 1, k) = rowQ[k];
    }
    b(2 * i) = p;
    b(2 * i + 1) = q;
  }
  cv::Matx<double, 8, 1> t;
  const cv::Mat w = [&] {
    cv::Mat values;
    cv::SVD::compute(cv::Mat(a), values, cv::SVD::NO_UV);
    return values;
  }();
  if (!(w.at<double>(7) > 1e-10 * w.at<double>(0))) {
    return makeError("three of the four corners are collinear; the plane's homography is degenerate");
  }
  if (!cv::solve(a, b, t, cv::DECOMP_LU)) return makeError("the plane's homography is degenerate");
  const cv::Matx33d hn(t(0), t(1), t(2), t(3), t(4), t(5), t(6), t(7), 1.0);
  cv::Matx33d h = td.inv() * hn * ts;
  if (std::abs(h(2, 2)) < 1e-300) return makeError("the plane's homography is degenerate");
  h *= 1.0 / h(2, 2);
  return h;
}

}  // namespace pw::metrology
