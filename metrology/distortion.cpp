#include "metrology/distortion.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>

#include "metrology/corridor_frame.h"

namespace pw::metrology {
namespace {

// The radial factor 1 + k1 r² + k2 r⁴ at normalised radius² r2.
double radialFactor(const RadialDistortion& d, double r2) { return 1.0 + r2 * (d.k1 + r2 * d.k2); }

cv::Matx33d cameraMatrix(const Intrinsics& k) {
  return {k.focalPx, 0, k.principalPointPx.x, 0, k.focalPx, k.principalPointPx.y, 0, 0, 1};
}

// The normalised radius² beyond which the model folds back (its slope turns
// negative), or infinity.
double foldRadius2(const RadialDistortion& d) {
  // slope(r2) = 1 + 3 k1 r2 + 5 k2 r2², a quadratic in r2: its smallest positive root.
  const double a = 5.0 * d.k2, b = 3.0 * d.k1;
  if (a == 0) return b < 0 ? -1.0 / b : INFINITY;
  const double disc = b * b - 4.0 * a;
  if (disc < 0) return INFINITY;
  double best = INFINITY;
  for (double root : {(-b - std::sqrt(disc)) / (2 * a), (-b + std::sqrt(disc)) / (2 * a)}) {
    if (root > 0) best = std::min(best, root);
  }
  return best;
}

// Photo pixels to pinhole pixels in place (OpenCV's undistortPoints, iterated to
// 1e-12); false for each point where the model does not invert. OpenCV's fixed-point
// iteration stops without saying whether it settled: each point found is checked to
// lie on the model's one-to-one part and to map back onto its photo pixel.
std::vector<bool> undistortInPlace(const Intrinsics& camera, std::vector<cv::Point2d>& points) {
  const RadialDistortion& d = camera.distortion;
  const std::vector<cv::Point2d> photo = points;
  const cv::Matx<double, 1, 4> coefficients(d.k1, d.k2, 0, 0);
  cv::undistortPoints(photo, points, cameraMatrix(camera), coefficients, cv::noArray(), cameraMatrix(camera),
                      cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 200, 1e-12));
  const double fold2 = foldRadius2(d);
  std::vector<bool> ok(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    const glm::dvec2 p(points[i].x, points[i].y);
    const glm::dvec2 x = (p - camera.principalPointPx) / camera.focalPx;
    ok[i] = std::isfinite(p.x) && std::isfinite(p.y) && glm::dot(x, x) < fold2 &&
            glm::length(distortPixel(camera, p) - glm::dvec2(photo[i].x, photo[i].y)) <= 1e-6 * std::max(1.0, camera.focalPx);
  }
  return ok;
}

}  // namespace

glm::dvec2 distortPixel(const Intrinsics& camera, const glm::dvec2& pinholePx) {
  const RadialDistortion& d = camera.distortion;
  if (d.isNone()) return pinholePx;
  const glm::dvec2 x = (pinholePx - camera.principalPointPx) / camera.focalPx;
  return camera.principalPointPx + camera.focalPx * x * radialFactor(d, glm::dot(x, x));
}

std::optional<glm::dvec2> undistortPixel(const Intrinsics& camera, const glm::dvec2& photoPx) {
  if (camera.distortion.isNone()) return photoPx;
  std::vector<cv::Point2d> points{{photoPx.x, photoPx.y}};
  return undistortInPlace(camera, points)[0] ? std::optional(glm::dvec2(points[0].x, points[0].y)) : std::nullopt;
}

Status checkDistortion(const RadialDistortion& lens) {
  if (!std::isfinite(lens.k1) || !std::isfinite(lens.k2)) return makeError("the distortion coefficients must be finite numbers");
  return {};
}

bool insideFold(const Intrinsics& camera, const glm::dvec2& pinholePx) {
  if (camera.distortion.isNone()) return true;
  const glm::dvec2 x = (pinholePx - camera.principalPointPx) / camera.focalPx;
  return glm::dot(x, x) < foldRadius2(camera.distortion);
}

std::string distortionText(const RadialDistortion& lens) {
  char text[64];
  std::snprintf(text, sizeof text, "k1 %.4f, k2 %.4f", lens.k1, lens.k2);
  return text;
}

void undistortionMaps(const Intrinsics& camera, cv::Size pinholeSize, const glm::dvec2& offsetPx, cv::Mat& mapX,
                      cv::Mat& mapY) {
  const RadialDistortion& d = camera.distortion;
  Intrinsics shifted = camera;
  shifted.principalPointPx += offsetPx;
  // OpenCV's own map: the new camera is the same lens moved by the offset.
  const cv::Matx<double, 1, 4> coefficients(d.k1, d.k2, 0, 0);
  cv::initUndistortRectifyMap(cameraMatrix(camera), coefficients, cv::noArray(), cameraMatrix(shifted), pinholeSize,
                              CV_32FC1, mapX, mapY);
}

void distortionMaps(const Intrinsics& camera, cv::Size photoSize, const glm::dvec2& offsetPx, cv::Mat& mapX,
                    cv::Mat& mapY) {
  mapX.create(photoSize, CV_32FC1);
  mapY.create(photoSize, CV_32FC1);
  cv::parallel_for_(cv::Range(0, photoSize.height), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      std::vector<cv::Point2d> row(photoSize.width);
      for (int x = 0; x < photoSize.width; ++x) row[x] = cv::Point2d(x, y);
      const std::vector<bool> ok = undistortInPlace(camera, row);
      float* mx = mapX.ptr<float>(y);
      float* my = mapY.ptr<float>(y);
      for (int x = 0; x < photoSize.width; ++x) {
        mx[x] = ok[x] ? static_cast<float>(row[x].x + offsetPx.x) : -1.0f;
        my[x] = ok[x] ? static_cast<float>(row[x].y + offsetPx.y) : -1.0f;
      }
    }
  });
}

}  // namespace pw::metrology
