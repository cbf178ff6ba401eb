// Single-view metrology of a corridor: the one entry point.
//
// From one shot (photo size, focal length, principal point, camera height and/or a
// reference length, eight corners) to the corridor's true width, height and length
// with a standard deviation each, the vanishing geometry, the camera's full pose in
// the model frame (corridor_frame.h) and the eight fitted corners in it.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

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
  // The other inputs' standard deviations (issue 23): each is carried into the
  // dimensions by measuring again at the input moved by one sigma either way (half the
  // difference, so a focal length far off is not linearised), and combined with the
  // corners' in quadrature. 0 treats the input as exact (today's default).
  // The focal length's, relative (0.25: 25%), moved as f·e^{±σ}.
  double focalSigmaRelative = 0.0;
  // Of the principal point's u and v each (px).
  double principalPointSigmaPx = 0.0;
  // Of the lens's radial k1 (distortion.h, normalised units).
  double distortionSigmaK1 = 0.0;
  // How the sources are named in "(mostly: the assumed focal length)".
  std::string focalSigmaName = "the focal length";
  std::string cameraHeightSigmaName = "the camera height";
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

// One input's share of the uncertainty: the dimensions' standard deviations from it
// alone (their squares add up to Measurement::sigma's).
struct SigmaSource {
  std::string key;   // "corners", "focal_length", "camera_height", "principal_point", "distortion"
  std::string name;  // as said after "mostly:" ("the assumed focal length")
  Dimensions sigma;
};

struct Measurement {
  Method method = Method::kGeneral;
  Dimensions size;
  // One standard deviation: every source of sigmaSources in quadrature (the corners'
  // first order, uncertainty.h; the others' by measuring again, MeasureOptions).
  Dimensions sigma;
  std::vector<SigmaSource> sigmaSources;  // the corners' first, then those with a sigma
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

// Which dimension: 0 width, 1 height, 2 length.
double dimensionOf(const Dimensions& d, int which);
// The corners' share of the sigma (m.sigma when the sources are not split).
Dimensions cornerSigma(const Measurement& m);
// The source with the largest share of that dimension's sigma (null without sources).
const SigmaSource* dominantSigmaSource(const Measurement& m, int which);

// Beyond these a measured box is no interior a photo is taken in (a hall or a hangar
// is under 100 m across and 60 m high): the scale is what to check, its units first
// (a camera height or reference length given in centimetres or millimetres scales
// every length by 100 or 1000; a corridor 2-4 m wide is then 200 m wide or more).
inline constexpr double kPlausibleWidthM = 100, kPlausibleHeightM = 60, kPlausibleLengthM = 1000;
// One line saying so where the box measured is larger than any of those, naming what
// gave the scale (the shot's camera height, else its reference length); none
// otherwise. The measurement stands: the line is a warning, for the person to check.
std::optional<std::string> implausibleSize(const Shot& shot, const Measurement& m);
// "2.6 m ± 0.3": the sigma to one significant digit (two when it starts with 1 or 2),
// the value to the same decimal place (millimetres at most, metres at least);
// `plusMinus` "+/-" where the font has no ±.
std::string dimensionText(double valueM, double sigmaM, const char* plusMinus = "\u00b1");
// dimensionText with its largest source: "2.6 m ± 0.3 (mostly: the assumed focal length)";
// without the parenthesis when the corners are the only source.
std::string dimensionWithSource(const Measurement& m, int which, const char* plusMinus = "\u00b1");

// Pixel (u, v) of a model-frame point as the measured camera sees it (through the
// lens's distortion), and its depth (corridor_frame.h's projectToPixel).
glm::dvec3 projectWithMeasurement(const Measurement& m, const glm::dvec3& pointM);

}  // namespace pw::metrology
