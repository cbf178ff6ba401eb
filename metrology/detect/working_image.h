// The photo at the working resolution detection runs on, with its colour gradient.
#pragma once

#include <glm/glm.hpp>
#include <opencv2/core/mat.hpp>

namespace pw::metrology::detect {

struct WorkingImage {
  cv::Mat bgr;           // CV_8UC3, the photo scaled by `scale`
  cv::Mat gray;          // CV_8U
  cv::Mat gradX, gradY;  // CV_32F, grey levels per pixel, of the colour channel whose gradient is strongest
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
};

// Scales `photoBgr` (CV_8UC3) down with area averaging so that its longer side is at
// most `maxSidePx`, and computes the gradients. A colour gradient (the strongest
// channel's, as in Di Zenzo's colour edges) keeps hue-only edges, e.g. a red brick
// wall against a grey floor of the same brightness.
WorkingImage makeWorkingImage(const cv::Mat& photoBgr, int maxSidePx);

}  // namespace pw::metrology::detect
