#include "editor/edit/warnings.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pw::edit {

std::vector<std::string> measurementWarnings(const metrology::Shot& shot, const metrology::Measurement& m,
                                             const metrology::MeasureOptions& options, int* culpritCorner) {
  std::vector<std::string> out;
  if (culpritCorner) *culpritCorner = -1;
  if (auto large = metrology::implausibleSize(shot, m)) out.push_back(*large);
  char line[256];
  // The corners' share only: the advice is where to put them (the focal length's and
  // the camera height's shares are said beside each dimension).
  const metrology::Dimensions sigma = metrology::cornerSigma(m);
  const struct {
    const char* name;
    double value, sigma;
    const char* advice;
  } dims[] = {
      {"width", m.size.widthM, sigma.widthM, "place P5/P6 and P7/P8 farther apart, or more precisely"},
      {"height", m.size.heightM, sigma.heightM, "place P5/P7 and P6/P8 farther apart, or more precisely"},
      {"length", m.size.lengthM, sigma.lengthM,
       "the near corners P5..P8 are too close to the far wall's lines; place them nearer the camera, or more "
       "precisely"},
  };
  for (const auto& d : dims) {
    if (d.value <= 0 || d.sigma / d.value <= kUncertainFraction) continue;
    std::snprintf(line, sizeof line, "the %s is uncertain to +-%.0f%% (%.2f m at %.1f px per corner): %s", d.name,
                  100.0 * d.sigma / d.value, d.sigma, m.cornerSigmaPx, d.advice);
    out.push_back(line);
  }

  // The corner that breaks the box: least squares spreads one misplaced corner's error
  // over the others (P6 moved by (25, -20) px left P8 the farthest from the fitted box),
  // so each corner in turn is put where the fit says and the box refitted; the one
  // whose move leaves the smallest error is the one to check.
  if (m.reprojectionRmsPx > kCornerOffPx / 2) {
    double worstPx = 0;
    for (int k = 0; k < metrology::kCornerCount; ++k) {
      worstPx = std::max(worstPx, glm::length(m.reprojectedPx[k] - shot.cornersPx[k]));
    }
    int culprit = -1;
    double bestRms = m.reprojectionRmsPx;
    // Which corner breaks the box, not the lens: each refit without a distortion fit
    // (a drag off the box took 33 ms a step with it, twice a 60 fps frame).
    metrology::MeasureOptions refitOptions = options;
    refitOptions.distortionFromCorners = false;
    for (int k = 0; k < metrology::kCornerCount && worstPx > kCornerOffPx; ++k) {
      metrology::Shot moved = shot;
      moved.cornersPx[k] = m.reprojectedPx[k];
      auto refit = metrology::measureCorridor(moved, refitOptions);
      if (refit && refit->reprojectionRmsPx < bestRms) bestRms = refit->reprojectionRmsPx, culprit = k;
    }
    if (worstPx > kCornerOffPx && culprit >= 0) {
      std::snprintf(line, sizeof line,
                    "the corners do not make one box (%.1f px from it at worst): check %s first, %.1f px off",
                    worstPx, metrology::cornerName(culprit), glm::length(m.reprojectedPx[culprit] - shot.cornersPx[culprit]));
      out.push_back(line);
      if (culpritCorner) *culpritCorner = culprit;
    }
  }

  if (m.vanishing.corridor.residualPx > kVanishingResidualPx) {
    std::snprintf(line, sizeof line,
                  "the receding edges miss their vanishing point by %.1f px (RMS): check P1..P4 against P5..P8",
                  m.vanishing.corridor.residualPx);
    out.push_back(line);
  }

  if (m.reference && !m.reference->usedForScale && std::abs(m.reference->errorPercent) > kReferencePercent) {
    std::snprintf(line, sizeof line, "the reference %s-%s measures %.3f m, not the %.3f m given (%+.1f%%)",
                  metrology::cornerName(m.reference->from), metrology::cornerName(m.reference->to), m.reference->measuredM,
                  m.reference->givenM, m.reference->errorPercent);
    out.push_back(line);
  }
  return out;
}

}  // namespace pw::edit
