// A small dense Levenberg-Marquardt solver for the box fit (8 parameters, 16
// residuals): enough for a few iterations on a problem this size, no dependency
// beyond OpenCV's linear algebra.
#pragma once

#include <functional>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "base/result.h"

namespace pw::metrology {

// Fills `residuals` (residualCount values) for `parameters`; returns false where the
// model is undefined there (e.g. a point behind the camera), which the solver treats
// as an infinitely bad step.
using ResidualFunction = std::function<bool(const std::vector<double>& parameters, std::vector<double>& residuals)>;

struct LeastSquaresOptions {
  int maxIterations = 100;
  double relativeStepTolerance = 1e-12;  // stop when |dp| <= tol (|p| + tol)
  double gradientTolerance = 1e-14;      // stop when max |J^T r| falls below this
};

struct LeastSquaresResult {
  std::vector<double> parameters;
  std::vector<double> residuals;
  cv::Mat jacobian;  // residualCount x parameterCount (CV_64F) at the solution
  double cost = 0;   // sum of squared residuals
  int iterations = 0;
};

// Jacobian of `f` at `x` by central differences with steps `steps` (one per
// parameter). Fails where f is undefined at a probe.
Result<cv::Mat> numericJacobian(const ResidualFunction& f, const std::vector<double>& x, const std::vector<double>& steps,
                                int residualCount);

// Minimises Σ r_i(p)² from `start` (Marquardt's damping of J^T J's diagonal,
// Nocedal & Wright 10.3), with the Jacobian by central differences using `steps`.
// Fails when f is undefined at the start.
Result<LeastSquaresResult> levenbergMarquardt(const ResidualFunction& f, std::vector<double> start,
                                              const std::vector<double>& steps, int residualCount,
                                              const LeastSquaresOptions& options = {});

// The x in [lo, hi] that minimises f of one variable: the best of `start` and
// gridSteps + 1 evenly spaced samples, then golden-section search (Press et al.,
// Numerical Recipes 10.2) within one grid step either side of it, `goldenSteps`
// times (each narrows the bracket by 0.618). The grid keeps a function with several
// minima from the wrong one; f may return infinity where it is undefined.
double minimizeOnInterval(const std::function<double(double)>& f, double lo, double hi, int gridSteps, int goldenSteps,
                          double start);

}  // namespace pw::metrology
