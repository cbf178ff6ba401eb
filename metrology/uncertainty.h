// First-order propagation of corner-localisation error to the measured dimensions,
// as Criminisi, Reid and Zisserman do in "Single View Metrology" (IJCV 40(2), 2000,
// section 5): a quantity y = f(x) of inputs with covariance Λx has covariance
// Λy = ∇f Λx ∇fᵀ to first order.
#pragma once

#include <vector>

#include <opencv2/core/mat.hpp>

#include "base/result.h"

namespace pw::metrology {

// J Λ Jᵀ (all CV_64F; J is m x n, Λ n x n).
cv::Mat propagateCovariance(const cv::Mat& jacobian, const cv::Mat& inputCovariance);

// Covariance of the parameters of a least-squares fit to image measurements that
// each have standard deviation `sigmaPx`, from the Jacobian of the residuals (px)
// with respect to the parameters at the solution: σ² (JᵀJ)⁻¹ (Hartley & Zisserman,
// 2nd ed., 5.2.3, backward propagation). Fails when JᵀJ is singular, i.e. the
// measurements do not determine the parameters.
Result<cv::Mat> fitCovariance(const cv::Mat& residualJacobian, double sigmaPx);

// Square roots of the diagonal (negative round-off clamped to 0).
std::vector<double> standardDeviations(const cv::Mat& covariance);

}  // namespace pw::metrology
