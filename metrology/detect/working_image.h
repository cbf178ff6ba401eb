// The photo at the working resolution detection runs on, with its colour gradient.
#pragma once

#include <cmath>

#include <glm/glm.hpp>
#include <opencv2/core/mat.hpp>

#include "metrology/corridor_frame.h"

namespace pw::metrology::detect {

// A gradient above this (grey levels per pixel, about a 12-level step) is an edge.
inline constexpr float kEdgeGreyPerPx = 6.0f;

struct WorkingImage {
  cv::Mat bgr;           // CV_8UC3, the photo scaled by `scale`
  cv::Mat gray;          // CV_8U
  cv::Mat gradX, gradY;  // CV_32F, grey levels per pixel, of the colour channel whose gradient is strongest
  // CV_8U, non-zero where a pixel within one of this one has |gradX| (edgeX) or
  // |gradY| (edgeY) above kEdgeGreyPerPx: a one-lookup edge test for the scans.
  cv::Mat edgeX, edgeY;
  double scale = 1.0;    // working pixels per full-resolution pixel (<= 1)

  // Pixel centres map as u_working = (u_full + 0.5) * scale - 0.5 (area resampling).
  glm::dvec2 toWorking(glm::dvec2 full) const { return (full + 0.5) * scale - 0.5; }
  glm::dvec2 toFull(glm::dvec2 working) const { return (working + 0.5) / scale - 0.5; }
  // The same map on homogeneous points (points at infinity keep their direction).
  glm::dvec3 toWorking(glm::dvec3 full) const {
    return {scale * full.x + (0.5 * scale - 0.5) * full.z, scale * full.y + (0.5 * scale - 0.5) * full.z, full.z};
  }
  bool contains(glm::dvec2 p, double marginPx = 0) const {
    return p.x >= marginPx && p.y >= marginPx && p.x <= bgr.cols - 1 - marginPx && p.y <= bgr.rows - 1 - marginPx;
  }
  // Bilinear gradient at a working-resolution point (zero outside the image).
  glm::dvec2 gradient(glm::dvec2 p) const;
  // Whether an edge crossing `normal` runs within a pixel of p (nearest-pixel test on
  // edgeX or edgeY, whichever axis the normal is closer to).
  bool edgeNear(glm::dvec2 p, glm::dvec2 normal) const {
    const int x = static_cast<int>(p.x + 0.5), y = static_cast<int>(p.y + 0.5);
    if (x < 0 || y < 0 || x >= edgeX.cols || y >= edgeX.rows) return false;
    return (std::abs(normal.x) >= std::abs(normal.y) ? edgeX : edgeY).at<uchar>(y, x) != 0;
  }
};

// Scales `photoBgr` (CV_8UC3) down by the smallest whole factor that brings its
// longer side to at most `maxSidePx` (area averaging), and computes the gradients. A colour gradient (the strongest
// channel's, as in Di Zenzo's colour edges) keeps hue-only edges, e.g. a red brick
// wall against a grey floor of the same brightness.
WorkingImage makeWorkingImage(const cv::Mat& photoBgr, int maxSidePx);

// The working copy of the pinhole photo behind `work` when the photo was taken
// through `lens` (full-resolution pixels): `work` undistorted at its own resolution
// (bicubic), with its gradients. The same scale and pixel-centre map as `work`.
WorkingImage undistortWorkingImage(const WorkingImage& work, const Intrinsics& lens);

// The colour gradient of `bgr` (CV_8UC3): per pixel, Sobel's derivatives of the
// channel whose gradient is strongest, in grey levels per pixel (CV_32F each).
void colourGradient(const cv::Mat& bgr, cv::Mat& gradX, cv::Mat& gradY);

}  // namespace pw::metrology::detect
