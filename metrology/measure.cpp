#include "metrology/measure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "metrology/box_fit.h"
#include "metrology/least_squares.h"
#include "metrology/seed_method.h"
#include "metrology/shot_check.h"
#include "metrology/uncertainty.h"

namespace pw::metrology {

const char* methodName(Method method) { return method == Method::kSeed ? "seed" : "general"; }

const char* distortionSourceName(DistortionSource source) {
  switch (source) {
    case DistortionSource::kNone: return "none";
    case DistortionSource::kShot: return "shot";
    case DistortionSource::kCorners: return "corners";
  }
  return "?";
}

namespace {

// What either method gives, in metres for the camera height it was run with; the
// vector form [W, H, L, camera x, y, z, yaw, pitch, roll] (metres, radians) is what
// the uncertainty is propagated to.
enum Output : int { kOutW = 0, kOutH, kOutL, kOutX, kOutY, kOutZ, kOutYaw, kOutPitch, kOutRoll, kOutputCount };

struct Solution {
  double widthM = 0, heightM = 0, lengthM = 0;
  CameraPose pose;
  int iterations = 0;
};

std::vector<double> outputsOf(const Solution& s) {
  return {s.widthM,         s.heightM,        s.lengthM,
          s.pose.positionM.x, s.pose.positionM.y, s.pose.positionM.z,
          glm::radians(s.pose.yawDeg), glm::radians(s.pose.pitchDeg), glm::radians(s.pose.rollDeg)};
}

// Metric outputs times `scale` (angles unchanged).
std::vector<double> scaled(std::vector<double> o, double scale) {
  for (int i = kOutW; i <= kOutZ; ++i) o[i] *= scale;
  return o;
}

// The factor that makes the reference length come out right, for a box measured at
// some provisional camera height.
Result<double> referenceScale(const ReferenceLength& ref, const std::vector<double>& o) {
  const auto corners = corridorCorners(o[kOutW], o[kOutH], o[kOutL]);
  const double d = glm::length(corners[ref.from] - corners[ref.to]);
  if (!(d > 1e-12)) return makeError("the reference corners coincide in the fitted box");
  return ref.lengthM / d;
}

Solution seedSolution(const SeedConstruction& c, double h) {
  Solution s;
  s.widthM = c.widthM;
  s.heightM = c.heightM;
  s.lengthM = c.lengthM;
  // The paper's camera looks straight down the corridor: no yaw, no pitch.
  s.pose = makeCameraPose(0.0, 0.0, c.rollDeg, glm::dvec3(c.cameraXM, h, c.nearDepthM));
  return s;
}

// The floor's vanishing line for a camera pose: l = K⁻ᵀ n with n the up direction in
// OpenCV camera coordinates (Hartley & Zisserman, result 8.16).
ImageLine horizonOf(const Intrinsics& k, const CameraPose& pose, const glm::dvec2& floorPx) {
  const glm::dvec3 upGl = glm::transpose(pose.worldFromCamera) * glm::dvec3(0, 1, 0);
  const glm::dvec3 n(upGl.x, -upGl.y, -upGl.z);
  const double f = k.focalPx, cx = k.principalPointPx.x, cy = k.principalPointPx.y;
  glm::dvec3 l(n.x / f, n.y / f, n.z - (cx * n.x + cy * n.y) / f);
  l /= glm::length(glm::dvec2(l));
  if (signedDistancePx(l, floorPx) < 0) l = -l;
  return l;
}

bool finite(double v) { return std::isfinite(v); }
bool finite(const glm::dvec2& v) { return finite(v.x) && finite(v.y); }
bool finite(const glm::dvec3& v) { return finite(v.x) && finite(v.y) && finite(v.z); }

bool allFinite(const Measurement& m) {
  bool ok = finite(m.size.widthM) && finite(m.size.heightM) && finite(m.size.lengthM) && finite(m.sigma.widthM) &&
            finite(m.sigma.heightM) && finite(m.sigma.lengthM) && finite(m.horizon) && finite(m.cameraHeightM) &&
            finite(m.pose.positionM) && finite(m.pose.yawDeg) && finite(m.pose.pitchDeg) && finite(m.pose.rollDeg) &&
            finite(m.poseSigma.yawDeg) && finite(m.poseSigma.pitchDeg) && finite(m.poseSigma.rollDeg) &&
            finite(m.poseSigma.positionM) && finite(m.reprojectionRmsPx) && finite(m.vanishing.corridor.px) &&
            finite(m.vanishing.corridor.residualPx) && finite(m.vanishing.horizontal.homogeneous) &&
            finite(m.vanishing.vertical.homogeneous) && finite(m.vanishing.rollDeg);
  for (int c = 0; c < 3; ++c) ok = ok && finite(m.pose.worldFromCamera[c]);
  for (int i = 0; i < kCornerCount; ++i) ok = ok && finite(m.cornersM[i]) && finite(m.reprojectedPx[i]);
  if (m.reference) ok = ok && finite(m.reference->measuredM) && finite(m.reference->errorPercent);
  return ok;
}

// The measurement of a pinhole shot: its corners where a camera without distortion
// would show them, `k` without distortion.
Result<Measurement> measurePinhole(const Shot& shot, const Intrinsics& k, const MeasureOptions& options) {
  auto vanishing = corridorVanishing(shot.cornersPx);
  if (!vanishing) return vanishing.error();

  // Without a camera height, measure at a provisional height of 1 m and rescale so
  // that the reference length comes out right (the image fixes shape, not size).
  const bool heightGiven = shot.cameraHeightM.has_value();
  const double h = heightGiven ? *shot.cameraHeightM : 1.0;

  Measurement m;
  m.method = options.method;
  m.cornerSigmaPx = options.cornerSigmaPx;
  m.vanishing = *vanishing;
  m.camera = k;

  // The raw solution (at height h), and the covariance of its outputs per 1 px².
  Solution solution;
  cv::Mat outputCovariance;
  // d(final outputs)/d(raw outputs) is folded in below through a numeric Jacobian of
  // the final outputs, so that the reference rescaling carries its own uncertainty.
  std::function<Result<std::vector<double>>(const std::vector<double>&)> finalize =
      [&](const std::vector<double>& o) -> Result<std::vector<double>> {
    if (heightGiven) return o;
    auto s = referenceScale(*shot.reference, o);
    if (!s) return s.error();
    return scaled(o, *s);
  };

  if (options.method == Method::kGeneral) {
    auto fit = fitCorridorBox(shot.cornersPx, k, h, *vanishing);
    if (!fit) return fit.error();
    solution.widthM = fit->widthM;
    solution.heightM = fit->heightM;
    solution.lengthM = fit->lengthM;
    solution.pose = fit->pose;
    solution.iterations = fit->iterations;
    // Outputs as a function of the fitted parameters (camera y is the fixed h).
    const cv::Mat& pc = fit->parameterCovariance;
    cv::Mat g = cv::Mat::zeros(kOutputCount, kBoxParameterCount, CV_64F);
    g.at<double>(kOutW, kWidth) = g.at<double>(kOutH, kHeight) = g.at<double>(kOutL, kLength) = 1;
    g.at<double>(kOutX, kCameraX) = g.at<double>(kOutZ, kCameraZ) = 1;
    g.at<double>(kOutYaw, kYaw) = g.at<double>(kOutPitch, kPitch) = g.at<double>(kOutRoll, kRoll) = 1;
    outputCovariance = propagateCovariance(g, pc);
  } else {
    auto seed = seedConstruct(shot.cornersPx, k.focalPx, h);
    if (!seed) return seed.error();
    solution = seedSolution(*seed, h);
    // The construction is a closed-form function of the 16 corner coordinates:
    // differentiate it numerically (Criminisi et al.'s first-order propagation).
    std::vector<double> x(2 * kCornerCount);
    for (int i = 0; i < kCornerCount; ++i) {
      x[2 * i] = shot.cornersPx[i].x;
      x[2 * i + 1] = shot.cornersPx[i].y;
    }
    ResidualFunction f = [&](const std::vector<double>& q, std::vector<double>& out) {
      std::array<glm::dvec2, kCornerCount> corners{};
      for (int i = 0; i < kCornerCount; ++i) corners[i] = glm::dvec2(q[2 * i], q[2 * i + 1]);
      auto c = seedConstruct(corners, k.focalPx, h);
      if (!c) return false;
      out = outputsOf(seedSolution(*c, h));
      return true;
    };
    auto g = numericJacobian(f, x, std::vector<double>(x.size(), 1e-3), kOutputCount);
    if (!g) return makeError("the seed construction is degenerate next to these corners; check them or use --method general");
    outputCovariance = *g * g->t();
  }

  // Final outputs and their covariance: corner noise (per 1 px², times σ²) through
  // the rescaling, plus the camera height's own uncertainty (the outputs' metric part
  // is proportional to h).
  const std::vector<double> raw = outputsOf(solution);
  auto finalOutputs = finalize(raw);
  if (!finalOutputs) return finalOutputs.error();
  ResidualFunction finalF = [&](const std::vector<double>& q, std::vector<double>& out) {
    auto r = finalize(q);
    if (!r) return false;
    out = *r;
    return true;
  };
  std::vector<double> steps(kOutputCount);
  for (int i = 0; i < kOutputCount; ++i) steps[i] = 1e-7 * std::max(1.0, std::abs(raw[i]));
  auto gFinal = numericJacobian(finalF, raw, steps, kOutputCount);
  if (!gFinal) return gFinal.error();
  cv::Mat covariance = propagateCovariance(*gFinal, outputCovariance) * (options.cornerSigmaPx * options.cornerSigmaPx);
  {
    const std::vector<double> sdCorners = standardDeviations(covariance);
    m.sigmaSources.push_back({"corners", "the corners", {sdCorners[kOutW], sdCorners[kOutH], sdCorners[kOutL]}});
  }
  if (heightGiven && options.cameraHeightSigmaM > 0) {
    cv::Mat dh = cv::Mat::zeros(kOutputCount, 1, CV_64F);
    for (int i = kOutW; i <= kOutZ; ++i) dh.at<double>(i) = (*finalOutputs)[i] / h;
    covariance += dh * dh.t() * (options.cameraHeightSigmaM * options.cameraHeightSigmaM);
    const double r = options.cameraHeightSigmaM / h;  // the metric outputs are proportional to h
    m.sigmaSources.push_back({"camera_height", options.cameraHeightSigmaName,
                              {std::abs((*finalOutputs)[kOutW]) * r, std::abs((*finalOutputs)[kOutH]) * r,
                               std::abs((*finalOutputs)[kOutL]) * r}});
  }
  const std::vector<double> sd = standardDeviations(covariance);
  const std::vector<double>& o = *finalOutputs;

  m.size = {o[kOutW], o[kOutH], o[kOutL]};
  m.sigma = {sd[kOutW], sd[kOutH], sd[kOutL]};
  m.cameraHeightM = o[kOutY];
  m.pose = makeCameraPose(glm::degrees(o[kOutYaw]), glm::degrees(o[kOutPitch]), glm::degrees(o[kOutRoll]),
                          glm::dvec3(o[kOutX], o[kOutY], o[kOutZ]));
  m.poseSigma.yawDeg = glm::degrees(sd[kOutYaw]);
  m.poseSigma.pitchDeg = glm::degrees(sd[kOutPitch]);
  m.poseSigma.rollDeg = glm::degrees(sd[kOutRoll]);
  m.poseSigma.positionM = glm::dvec3(sd[kOutX], sd[kOutY], sd[kOutZ]);
  m.iterations = solution.iterations;
  m.cornersM = corridorCorners(m.size.widthM, m.size.heightM, m.size.lengthM);
  auto reprojected = projectCorridor(k, m.pose, m.size.widthM, m.size.heightM, m.size.lengthM);
  if (!reprojected) return makeError("the measured box puts " + reprojected.message() + "; check the corners");
  m.reprojectedPx = *reprojected;
  double sum = 0;
  for (int i = 0; i < kCornerCount; ++i) {
    const glm::dvec2 d = m.reprojectedPx[i] - shot.cornersPx[i];
    sum += glm::dot(d, d);
  }
  m.reprojectionRmsPx = std::sqrt(sum / kCornerCount);
  m.horizon = horizonOf(k, m.pose, 0.5 * (shot.cornersPx[P5] + shot.cornersPx[P6]));

  if (shot.reference) {
    ReferenceCheck check;
    check.from = shot.reference->from;
    check.to = shot.reference->to;
    check.givenM = shot.reference->lengthM;
    check.measuredM = glm::length(m.cornersM[check.from] - m.cornersM[check.to]);
    check.errorPercent = 100.0 * (check.measuredM - check.givenM) / check.givenM;
    check.usedForScale = !heightGiven;
    m.reference = check;
  }
  if (!(m.size.widthM > 0) || !(m.size.heightM > 0) || !(m.size.lengthM > 0) || !allFinite(m)) {
    return makeError("the measurement is not finite or not positive; the corners are degenerate");
  }
  return m;
}

// The shot's corners where the pinhole would show them.
Result<std::array<glm::dvec2, kCornerCount>> pinholeCorners(const Shot& shot, const Intrinsics& k) {
  std::array<glm::dvec2, kCornerCount> out{};
  for (int i = 0; i < kCornerCount; ++i) {
    const std::optional<glm::dvec2> p = undistortPixel(k, shot.cornersPx[i]);
    if (!p) {
      return makeError(std::string("corner ") + cornerName(i) + " lies where the distortion (" +
                       distortionText(k.distortion) + ") does not invert");
    }
    out[i] = *p;
  }
  return out;
}

// Measures the shot through the lens `k`: the corners undistorted, the pinhole
// measured, and the reprojection taken back into the photo through the lens.
Result<Measurement> measureThroughLens(const Shot& shot, const Intrinsics& k, const MeasureOptions& options) {
  if (k.distortion.isNone()) return measurePinhole(shot, k, options);
  Shot pinhole = shot;
  auto corners = pinholeCorners(shot, k);
  if (!corners) return corners.error();
  pinhole.cornersPx = *corners;
  Intrinsics pinholeCamera = k;
  pinholeCamera.distortion = {};
  auto m = measurePinhole(pinhole, pinholeCamera, options);
  if (!m) return m;
  m->camera = k;
  double sum = 0;
  for (int i = 0; i < kCornerCount; ++i) {
    m->reprojectedPx[i] = distortPixel(k, m->reprojectedPx[i]);
    const glm::dvec2 d = m->reprojectedPx[i] - shot.cornersPx[i];
    sum += glm::dot(d, d);
  }
  m->reprojectionRmsPx = std::sqrt(sum / kCornerCount);
  return m;
}

// The k1 whose lens brings the corners onto the box: the RMS residual minimised over
// k1 in [-0.5, 0.3], then kept only when the corners fit
// (MeasureOptions::distortionFromCorners).
std::optional<Measurement> measureWithLensFromCorners(const Shot& shot, const Intrinsics& k, const MeasureOptions& options,
                                                      double rmsWithoutPx) {
  const auto measureAt = [&](double k1) -> std::optional<Measurement> {
    Intrinsics lens = k;
    lens.distortion = {k1, 0.0};
    auto m = measureThroughLens(shot, lens, options);
    if (!m) return std::nullopt;
    return std::move(*m);
  };
  const auto rmsAt = [&](double k1) {
    if (k1 == 0) return rmsWithoutPx;
    const auto m = measureAt(k1);
    return m ? m->reprojectionRmsPx : INFINITY;
  };
  const double k1 = minimizeOnInterval(rmsAt, -0.5, 0.3, 16, 30, 0.0);
  auto m = measureAt(k1);
  if (!m || !(m->reprojectionRmsPx < kDistortionFittedPx) || !(m->reprojectionRmsPx < rmsWithoutPx / 6.0)) {
    return std::nullopt;
  }
  m->distortionSource = DistortionSource::kCorners;
  return m;
}

// Half the spread of the dimensions measured with one input moved by -sigma and
// +sigma (`measureAt(-1)`, `measureAt(+1)`); one side's distance from `m` when the
// other does not measure; nullopt when neither does.
std::optional<Dimensions> spreadOf(const Measurement& m,
                                   const std::function<std::optional<Dimensions>(double)>& measureAt) {
  const std::optional<Dimensions> lo = measureAt(-1.0), hi = measureAt(1.0);
  const auto half = [](const Dimensions& a, const Dimensions& b, double f) {
    return Dimensions{std::abs(a.widthM - b.widthM) * f, std::abs(a.heightM - b.heightM) * f,
                      std::abs(a.lengthM - b.lengthM) * f};
  };
  if (lo && hi) return half(*lo, *hi, 0.5);
  if (lo) return half(*lo, m.size, 1.0);
  if (hi) return half(*hi, m.size, 1.0);
  return std::nullopt;
}

// The focal length's, the principal point's and the distortion's shares
// (MeasureOptions), added to m.sigmaSources and m.sigma.
void addInputSigmas(const Shot& shot, const MeasureOptions& options, Measurement& m) {
  MeasureOptions plain = options;
  plain.focalSigmaRelative = plain.principalPointSigmaPx = plain.distortionSigmaK1 = 0;
  plain.cameraHeightSigmaM = 0;
  const auto measureWith = [&](const Intrinsics& lens) -> std::optional<Dimensions> {
    auto r = measureThroughLens(shot, lens, plain);
    if (!r) return std::nullopt;
    return r->size;
  };
  if (options.focalSigmaRelative > 0) {
    auto s = spreadOf(m, [&](double side) {
      Intrinsics lens = m.camera;
      lens.focalPx *= std::exp(side * options.focalSigmaRelative);
      return measureWith(lens);
    });
    if (s) m.sigmaSources.push_back({"focal_length", options.focalSigmaName, *s});
  }
  if (options.principalPointSigmaPx > 0) {
    Dimensions total;
    bool any = false;
    for (int axis = 0; axis < 2; ++axis) {
      auto s = spreadOf(m, [&](double side) {
        Intrinsics lens = m.camera;
        lens.principalPointPx[axis] += side * options.principalPointSigmaPx;
        return measureWith(lens);
      });
      if (!s) continue;
      any = true;
      total.widthM = std::hypot(total.widthM, s->widthM);
      total.heightM = std::hypot(total.heightM, s->heightM);
      total.lengthM = std::hypot(total.lengthM, s->lengthM);
    }
    if (any) m.sigmaSources.push_back({"principal_point", "the principal point", total});
  }
  if (options.distortionSigmaK1 > 0) {
    auto s = spreadOf(m, [&](double side) {
      Intrinsics lens = m.camera;
      lens.distortion.k1 += side * options.distortionSigmaK1;
      if (!checkDistortion(lens.distortion)) return std::optional<Dimensions>{};
      return measureWith(lens);
    });
    if (s) m.sigmaSources.push_back({"distortion", "the lens distortion", *s});
  }
  Dimensions total;
  for (const SigmaSource& source : m.sigmaSources) {
    total.widthM = std::hypot(total.widthM, source.sigma.widthM);
    total.heightM = std::hypot(total.heightM, source.sigma.heightM);
    total.lengthM = std::hypot(total.lengthM, source.sigma.lengthM);
  }
  m.sigma = total;
}

}  // namespace

double dimensionOf(const Dimensions& d, int which) {
  return which == 0 ? d.widthM : which == 1 ? d.heightM : d.lengthM;
}

Dimensions cornerSigma(const Measurement& m) {
  for (const SigmaSource& s : m.sigmaSources) {
    if (s.key == "corners") return s.sigma;
  }
  return m.sigma;
}

std::optional<std::string> implausibleSize(const Shot& shot, const Measurement& m) {
  const Dimensions& d = m.size;
  if (d.widthM <= kPlausibleWidthM && d.heightM <= kPlausibleHeightM && d.lengthM <= kPlausibleLengthM) return std::nullopt;
  char size[160], scale[160];
  std::snprintf(size, sizeof size, "the corridor measures %.1f m wide, %.1f m high and %.1f m long", d.widthM, d.heightM,
                d.lengthM);
  if (shot.cameraHeightM) {
    std::snprintf(scale, sizeof scale, "the camera height (%g m)", *shot.cameraHeightM);
  } else if (shot.reference) {
    std::snprintf(scale, sizeof scale, "the reference length %s-%s (%g m)", cornerName(shot.reference->from),
                  cornerName(shot.reference->to), shot.reference->lengthM);
  } else {
    std::snprintf(scale, sizeof scale, "the scale");
  }
  return std::string(size) + ": no interior is that large; check that " + scale +
         " is in metres (not centimetres or millimetres), then the focal length";
}

const SigmaSource* dominantSigmaSource(const Measurement& m, int which) {
  const SigmaSource* best = nullptr;
  for (const SigmaSource& s : m.sigmaSources) {
    if (!best || dimensionOf(s.sigma, which) > dimensionOf(best->sigma, which)) best = &s;
  }
  return best;
}

std::string dimensionText(double valueM, double sigmaM, const char* plusMinus) {
  int decimals = 3;
  if (std::isfinite(sigmaM) && sigmaM > 0) {
    const double magnitude = std::floor(std::log10(sigmaM));
    const double leading = sigmaM / std::pow(10.0, magnitude);
    decimals = static_cast<int>(-magnitude) + (leading < 2.95 ? 1 : 0);
    decimals = std::clamp(decimals, 0, 3);
  }
  char text[96];
  std::snprintf(text, sizeof text, "%.*f m %s %.*f", decimals, valueM, plusMinus, decimals, sigmaM);
  return text;
}

std::string dimensionWithSource(const Measurement& m, int which, const char* plusMinus) {
  std::string text = dimensionText(dimensionOf(m.size, which), dimensionOf(m.sigma, which), plusMinus);
  const SigmaSource* top = dominantSigmaSource(m, which);
  if (top && m.sigmaSources.size() > 1) text += " (mostly: " + top->name + ")";
  return text;
}

Result<Measurement> measureCorridor(const Shot& shot, const MeasureOptions& options) {
  PW_TRY(checkShot(shot));
  if (!(options.cornerSigmaPx >= 0) || !std::isfinite(options.cornerSigmaPx)) {
    return makeError("the corner standard deviation must be a number of pixels >= 0");
  }
  if (!(options.cameraHeightSigmaM >= 0) || !std::isfinite(options.cameraHeightSigmaM)) {
    return makeError("the camera height's standard deviation must be a number of metres >= 0");
  }
  auto intrinsics = shotIntrinsics(shot);
  if (!intrinsics) return intrinsics.error();
  for (double v : {options.focalSigmaRelative, options.principalPointSigmaPx, options.distortionSigmaK1}) {
    if (!(v >= 0) || !std::isfinite(v)) return makeError("an input's standard deviation must be a number >= 0");
  }
  auto m = measureThroughLens(shot, *intrinsics, options);
  if (!m) return m;
  m->distortionSource = shot.distortion ? DistortionSource::kShot : DistortionSource::kNone;
  if (!shot.distortion && options.distortionFromCorners && m->reprojectionRmsPx > kDistortionResidualPx) {
    if (auto lens = measureWithLensFromCorners(shot, *intrinsics, options, m->reprojectionRmsPx)) *m = std::move(*lens);
  }
  addInputSigmas(shot, options, *m);
  if (!allFinite(*m)) return makeError("the measurement's uncertainty is not finite; the corners are degenerate");
  return m;
}

glm::dvec3 projectWithMeasurement(const Measurement& m, const glm::dvec3& pointM) {
  const glm::dvec3 p = projectToPixel(m.camera, m.pose, pointM);
  if (m.camera.distortion.isNone() || !(p.z > 0)) return p;
  return glm::dvec3(distortPixel(m.camera, glm::dvec2(p)), p.z);
}

}  // namespace pw::metrology
