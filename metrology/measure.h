// Single-view metrology of a corridor: the one entry point.
//
// From one shot (photo size, focal length, principal point, camera height and/or a
// reference length, eight corners) to the corridor's true width, height and length
// with a standard deviation each, the vanishing geometry, the camera's full pose in
// the model frame (corridor_frame.h) and the eight fitted corners in it.
#pragma once

#include <array>
#include <optional>

#include <glm/glm.hpp>

#include "base/result.h"
#include "metrology/corridor_frame.h"
#include "metrology/shot.h"
#include "metrology/vanishing.h"

namespace pw::metrology {

enum class Method {
  kGeneral,  // box_fit.h: full rotation, all eight corners, least squares (default)
  kSeed,     // seed_method.h: the paper's one-point-perspective construction
};
const char* methodName(Method method);

struct MeasureOptions {
  Method method = Method::kGeneral;
  // Standard deviation of each corner's u and v (px) for the uncertainties.
  double cornerSigmaPx = 1.0;
  // Standard deviation of the given camera height (m); 0 treats it as exact.
  double cameraHeightSigmaM = 0.0;
};

struct Dimensions {
  double widthM = 0;
  double heightM = 0;
  double lengthM = 0;
};

// Standard deviations of the pose (same units as CameraPose / positionM).
struct PoseSigma {
  double yawDeg = 0;
  double pitchDeg = 0;
  double rollDeg = 0;
  glm::dvec3 positionM{0.0};
};

// The reference length of the shot, compared with the measured box.
struct ReferenceCheck {
  int from = P3;
  int to = P4;
  double givenM = 0;
  double measuredM = 0;      // distance between the two fitted corners
  double errorPercent = 0;   // 100 (measured - given) / given
  bool usedForScale = false; // true when the shot has no camera height
};

struct Measurement {
  Method method = Method::kGeneral;
  Dimensions size;
  Dimensions sigma;  // one standard deviation, first order (uncertainty.h)
  double cornerSigmaPx = 1.0;
  CorridorVanishing vanishing;  // from the corners as given
  // The floor's vanishing line of the fitted camera (same sign convention as
  // CorridorVanishing::horizon).
  ImageLine horizon{0.0, 1.0, 0.0};
  Intrinsics camera;
  double cameraHeightM = 0;  // given, or derived from the reference length
  CameraPose pose;           // the camera in the model frame
  PoseSigma poseSigma;
  double reprojectionRmsPx = 0;  // RMS distance between the corners and the box's projection
  std::array<glm::dvec3, kCornerCount> cornersM{};       // fitted, model frame
  std::array<glm::dvec2, kCornerCount> reprojectedPx{};  // their projections
  std::optional<ReferenceCheck> reference;
  int iterations = 0;  // Levenberg-Marquardt iterations (general method)
};

// Checks the shot (shot_check.h), fits the vanishing geometry, then measures with
// the chosen method. The scale comes from the camera height when given (a reference
// length is then only checked), else from the reference length. Every number in a
// successful result is finite; failures are one line naming the problem.
Result<Measurement> measureCorridor(const Shot& shot, const MeasureOptions& options = {});

// Pixel (u, v) of a model-frame point as the measured camera sees it.
glm::dvec3 projectWithMeasurement(const Measurement& m, const glm::dvec3& pointM);

}  // namespace pw::metrology
