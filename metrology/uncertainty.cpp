#include "metrology/uncertainty.h"

#include <algorithm>
#include <cmath>

#include <opencv2/core.hpp>

namespace pw::metrology {

cv::Mat propagateCovariance(const cv::Mat& jacobian, const cv::Mat& inputCovariance) {
  return jacobian * inputCovariance * jacobian.t();
}

Result<cv::Mat> fitCovariance(const cv::Mat& residualJacobian, double sigmaPx) {
  const cv::Mat jtj = residualJacobian.t() * residualJacobian;
  // Scale to unit diagonal before judging the conditioning: the parameters mix metres
  // and radians, whose raw magnitudes say nothing about degeneracy.
  cv::Mat d(jtj.rows, 1, CV_64F);
  for (int i = 0; i < jtj.rows; ++i) {
    const double v = jtj.at<double>(i, i);
    if (!(v > 0) || !std::isfinite(v)) return makeError("the corners do not constrain every dimension of the box");
    d.at<double>(i) = 1.0 / std::sqrt(v);
  }
  const cv::Mat scaled = jtj.mul(d * d.t());
  cv::Mat w;
  cv::eigen(scaled, w);
  const double minEig = w.at<double>(w.rows - 1), maxEig = w.at<double>(0);
  if (!(minEig > 1e-12 * maxEig)) return makeError("the corners do not constrain every dimension of the box");
  cv::Mat inv;
  cv::invert(scaled, inv, cv::DECOMP_SVD);
  return cv::Mat(inv.mul(d * d.t()) * (sigmaPx * sigmaPx));
}

std::vector<double> standardDeviations(const cv::Mat& covariance) {
  std::vector<double> out(covariance.rows);
  for (int i = 0; i < covariance.rows; ++i) out[i] = std::sqrt(std::max(0.0, covariance.at<double>(i, i)));
  return out;
}

}  // namespace pw::metrology
