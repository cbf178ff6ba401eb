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
  // When the shot gives no distortion and the corners miss the fitted box by more than
  // kDistortionResidualPx (RMS), try a radial k1 (distortion.h) that the residual would
  // come from; it is kept only when it brings the corners onto the box (RMS under a
  // sixth of before, and under kDistortionFittedPx). Corners misplaced by hand do not
  // fit a lens, so they keep their residual (and the editor's warning).
  bool distortionFromCorners = true;
};
inline constexpr double kDistortionResidualPx = 0.5;
inline constexpr double kDistortionFittedPx = 0.5;

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

// Where the measurement's lens distortion (camera.distortion) came from.
enum class DistortionSource {
  kNone,     // the shot gives none and the corners show none: a pinhole
  kShot,     // the shot's `distortion`
  kCorners,  // estimated from the corners' residual (the shot gives none)
};
const char* distortionSourceName(DistortionSource source);

struct Measurement {
  Method method = Method::kGeneral;
  Dimensions size;
  Dimensions sigma;  // one standard deviation, first order (uncertainty.h)
  double cornerSigmaPx = 1.0;
  // From the corners as given, or where the pinhole would show them when the lens
  // has distortion (then so are the horizon and the vanishing points).
  CorridorVanishing vanishing;
  // The floor's vanishing line of the fitted camera (same sign convention as
  // CorridorVanishing::horizon).
  ImageLine horizon{0.0, 1.0, 0.0};
  Intrinsics camera;  // with the lens's distortion
  DistortionSource distortionSource = DistortionSource::kNone;
  double cameraHeightM = 0;  // given, or derived from the reference length
  CameraPose pose;           // the camera in the model frame
  PoseSigma poseSigma;
  // RMS distance between the corners and the box's projection (through the lens),
  // photo pixels.
  double reprojectionRmsPx = 0;
  std::array<glm::dvec3, kCornerCount> cornersM{};       // fitted, model frame
  std::array<glm::dvec2, kCornerCount> reprojectedPx{};  // their projections, photo pixels
  std::optional<ReferenceCheck> reference;
  int iterations = 0;  // Levenberg-Marquardt iterations (general method)
};

// Checks the shot (shot_check.h), takes the corners through the lens's distortion to
// where a pinhole would show them, fits the vanishing geometry, then measures with
// the chosen method. The scale comes from the camera height when given (a reference
// length is then only checked), else from the reference length. Every number in a
// successful result is finite; failures are one line naming the problem.
Result<Measurement> measureCorridor(const Shot& shot, const MeasureOptions& options = {});

// Pixel (u, v) of a model-frame point as the measured camera sees it (through the
// lens's distortion), and its depth (corridor_frame.h's projectToPixel).
glm::dvec3 projectWithMeasurement(const Measurement& m, const glm::dvec3& pointM);

}  // namespace pw::metrology
