#include "metrology/detect/working_image.h"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "metrology/distortion.h"

namespace pw::metrology::detect {

void colourGradient(const cv::Mat& bgr, cv::Mat& gradX, cv::Mat& gradY) {
  cv::Mat dx, dy;
  cv::Sobel(bgr, dx, CV_16S, 1, 0, 3);
  cv::Sobel(bgr, dy, CV_16S, 0, 1, 3);
  gradX.create(bgr.size(), CV_32F);
  gradY.create(bgr.size(), CV_32F);
  for (int y = 0; y < bgr.rows; ++y) {
    const cv::Vec3s* px = dx.ptr<cv::Vec3s>(y);
    const cv::Vec3s* py = dy.ptr<cv::Vec3s>(y);
    float* ox = gradX.ptr<float>(y);
    float* oy = gradY.ptr<float>(y);
    for (int x = 0; x < bgr.cols; ++x) {
      int best = 0, bestMag = -1;
      for (int c = 0; c < 3; ++c) {
        const int mag = px[x][c] * px[x][c] + py[x][c] * py[x][c];
        if (mag > bestMag) bestMag = mag, best = c;
      }
      // Sobel's 3x3 kernel sums 8 pixel differences' worth: /8 gives grey levels per pixel.
      ox[x] = px[x][best] * 0.125f;
      oy[x] = py[x][best] * 0.125f;
    }
  }
}

namespace {

// Grey, gradients and edge masks of w.bgr.
void computeGradients(WorkingImage& w) {
  cv::cvtColor(w.bgr, w.gray, cv::COLOR_BGR2GRAY);
  colourGradient(w.bgr, w.gradX, w.gradY);
  const cv::Mat kernel = cv::getStructuringElement(cv::MORPH_RECT, cv::Size(3, 3));
  cv::Mat strong;
  cv::compare(cv::abs(w.gradX), kEdgeGreyPerPx, strong, cv::CMP_GT);
  cv::dilate(strong, w.edgeX, kernel);
  cv::compare(cv::abs(w.gradY), kEdgeGreyPerPx, strong, cv::CMP_GT);
  cv::dilate(strong, w.edgeY, kernel);
}

}  // namespace

WorkingImage makeWorkingImage(const cv::Mat& photoBgr, int maxSidePx) {
  WorkingImage w;
  // Shrink by a whole factor k: OpenCV's area resampling then averages exact k x k
  // blocks (its fast path, several times quicker on 12 MP than a fractional factor),
  // and pixel centres map exactly as u_working = (u_full + 0.5) / k - 0.5. The last
  // (width mod k) columns and rows are left out of the working copy.
  const int longSide = std::max(photoBgr.cols, photoBgr.rows);
  const int k = std::max(1, (longSide + maxSidePx - 1) / maxSidePx);
  w.scale = 1.0 / k;
  if (k > 1) {
    const cv::Size size(photoBgr.cols / k, photoBgr.rows / k);
    cv::resize(photoBgr(cv::Rect(0, 0, size.width * k, size.height * k)), w.bgr, size, 0, 0, cv::INTER_AREA);
  } else {
    w.bgr = photoBgr;
  }
  computeGradients(w);
  return w;
}

WorkingImage undistortWorkingImage(const WorkingImage& work, const Intrinsics& lens) {
  // The lens in working pixels: k1 and k2 are normalised by the focal length, so
  // scaling the focal length and moving the principal point is the whole change.
  Intrinsics scaled = lens;
  scaled.focalPx = lens.focalPx * work.scale;
  scaled.principalPointPx = work.toWorking(lens.principalPointPx);
  cv::Mat mapX, mapY;
  undistortionMaps(scaled, work.bgr.size(), glm::dvec2(0.0), mapX, mapY);
  WorkingImage w;
  w.scale = work.scale;
  cv::remap(work.bgr, w.bgr, mapX, mapY, cv::INTER_CUBIC, cv::BORDER_REPLICATE);
  computeGradients(w);
  return w;
}

glm::dvec2 WorkingImage::gradient(glm::dvec2 p) const {
  if (!(p.x >= 0 && p.y >= 0 && p.x <= gradX.cols - 1 && p.y <= gradX.rows - 1)) return {0, 0};
  const int x0 = std::min(static_cast<int>(p.x), gradX.cols - 2 < 0 ? 0 : gradX.cols - 2);
  const int y0 = std::min(static_cast<int>(p.y), gradX.rows - 2 < 0 ? 0 : gradX.rows - 2);
  const int x1 = std::min(x0 + 1, gradX.cols - 1), y1 = std::min(y0 + 1, gradX.rows - 1);
  const double fx = p.x - x0, fy = p.y - y0;
  const auto sample = [&](const cv::Mat& m) {
    const double a = m.at<float>(y0, x0), b = m.at<float>(y0, x1), c = m.at<float>(y1, x0), d = m.at<float>(y1, x1);
    return (a * (1 - fx) + b * fx) * (1 - fy) + (c * (1 - fx) + d * fx) * fy;
  };
  return {sample(gradX), sample(gradY)};
}

}  // namespace pw::metrology::detect
