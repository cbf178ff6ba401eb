#include "metrology/least_squares.h"

#include <algorithm>
#include <cmath>

#include <opencv2/core.hpp>

namespace pw::metrology {

namespace {

double sumSquares(const std::vector<double>& r) {
  double s = 0;
  for (double v : r) s += v * v;
  return s;
}

bool allFinite(const std::vector<double>& r) {
  return std::all_of(r.begin(), r.end(), [](double v) { return std::isfinite(v); });
}

}  // namespace

Result<cv::Mat> numericJacobian(const ResidualFunction& f, const std::vector<double>& x, const std::vector<double>& steps,
                                int residualCount) {
  const int n = static_cast<int>(x.size());
  cv::Mat j(residualCount, n, CV_64F);
  std::vector<double> probe = x, plus(residualCount), minus(residualCount);
  for (int k = 0; k < n; ++k) {
    probe[k] = x[k] + steps[k];
    const bool okPlus = f(probe, plus) && allFinite(plus);
    probe[k] = x[k] - steps[k];
    const bool okMinus = f(probe, minus) && allFinite(minus);
    probe[k] = x[k];
    if (!okPlus || !okMinus) return makeError("the model is undefined next to the solution");
    for (int i = 0; i < residualCount; ++i) j.at<double>(i, k) = (plus[i] - minus[i]) / (2 * steps[k]);
  }
  return j;
}

Result<LeastSquaresResult> levenbergMarquardt(const ResidualFunction& f, std::vector<double> p,
                                              const std::vector<double>& steps, int residualCount,
                                              const LeastSquaresOptions& options) {
  const int n = static_cast<int>(p.size());
  LeastSquaresResult out;
  std::vector<double> r(residualCount), trialR(residualCount);
  if (!f(p, r) || !allFinite(r)) return makeError("the model is undefined at the starting point");
  double cost = sumSquares(r);
  double lambda = 1e-3;
  int iteration = 0;
  for (; iteration < options.maxIterations; ++iteration) {
    auto j = numericJacobian(f, p, steps, residualCount);
    if (!j) return j.error();
    const cv::Mat jt = j->t();
    const cv::Mat jtj = jt * *j;
    const cv::Mat g = jt * cv::Mat(r);
    double gradient = 0;
    for (int k = 0; k < n; ++k) gradient = std::max(gradient, std::abs(g.at<double>(k)));
    if (gradient < options.gradientTolerance) break;

    bool improved = false;
    bool converged = false;
    while (lambda < 1e12) {
      cv::Mat a = jtj.clone();
      for (int k = 0; k < n; ++k) a.at<double>(k, k) += lambda * std::max(jtj.at<double>(k, k), 1e-12);
      cv::Mat dp;
      if (!cv::solve(a, -g, dp, cv::DECOMP_CHOLESKY)) {
        lambda *= 10;
        continue;
      }
      std::vector<double> trial = p;
      double stepNorm = 0, paramNorm = 0;
      for (int k = 0; k < n; ++k) {
        trial[k] += dp.at<double>(k);
        stepNorm += dp.at<double>(k) * dp.at<double>(k);
        paramNorm += p[k] * p[k];
      }
      if (std::sqrt(stepNorm) <= options.relativeStepTolerance * (std::sqrt(paramNorm) + options.relativeStepTolerance)) {
        converged = true;
        break;
      }
      if (f(trial, trialR) && allFinite(trialR)) {
        const double trialCost = sumSquares(trialR);
        if (trialCost < cost) {
          p = std::move(trial);
          r = trialR;
          const double decrease = cost - trialCost;
          cost = trialCost;
          lambda = std::max(lambda * 0.1, 1e-15);
          improved = true;
          converged = decrease <= 1e-30 + 1e-20 * cost;
          break;
        }
      }
      lambda *= 10;
    }
    if (converged || !improved) break;
  }
  auto j = numericJacobian(f, p, steps, residualCount);
  if (!j) return j.error();
  out.parameters = std::move(p);
  out.residuals = std::move(r);
  out.jacobian = *j;
  out.cost = cost;
  out.iterations = iteration;
  return out;
}

double minimizeOnInterval(const std::function<double(double)>& f, double lo, double hi, int gridSteps, int goldenSteps,
                          double start) {
  double best = start, bestValue = f(start);
  for (int i = 0; i <= gridSteps; ++i) {
    const double x = lo + (hi - lo) * i / gridSteps;
    const double v = f(x);
    if (v < bestValue) best = x, bestValue = v;
  }
  const double step = (hi - lo) / gridSteps, ratio = 0.5 * (std::sqrt(5.0) - 1.0);
  double a = best - step, b = best + step;
  double x1 = b - ratio * (b - a), x2 = a + ratio * (b - a), f1 = f(x1), f2 = f(x2);
  for (int it = 0; it < goldenSteps; ++it) {
    if (f1 < f2) {
      b = x2, x2 = x1, f2 = f1, x1 = b - ratio * (b - a), f1 = f(x1);
    } else {
      a = x1, x1 = x2, f1 = f2, x2 = a + ratio * (b - a), f2 = f(x2);
    }
  }
  const double x = 0.5 * (a + b);
  return f(x) <= bestValue ? x : best;
}

}  // namespace pw::metrology
