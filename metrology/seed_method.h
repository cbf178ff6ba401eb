// The seed paper's one-point-perspective constructions, step by step.
//
// Vimala K.S., Avinash N., Murali S., "Generating 3D Views of an Object from Images",
// section 2.1 (view metrology) and the algorithm's steps 1-4, as ../shared/METHOD.md
// derives them. The construction is 2D analytic geometry in the image, rotated about
// the vanishing point VP so that the horizon is horizontal (this removes the roll);
// v grows downwards and a drawing scale s (px per metre, any positive value: the
// results do not depend on it) turns metres into drawing pixels.
//   Step 1  VP and the horizon HL (the station point ST is placed at VP).
//   Step 2  ground line GL: horizontal, s·h below VP (h = camera height).
//   Step 3  picture plane line PP: horizontal, f above VP (f = focal length, px).
//   Step 4  width (2.1.1), height (2.1.2), depth and length (2.1.3).
// Exact for a pinhole camera whose optical axis is parallel to the corridor and
// passes through VP (only rolled); photowalk's general solution (box_fit.h) handles
// yaw and pitch.
#pragma once

#include <array>
#include <optional>

#include <glm/glm.hpp>

#include "base/result.h"
#include "metrology/shot.h"

namespace pw::metrology {

// One floor corner's constructions (all points in the rotated image, px).
struct SeedFloorPoint {
  glm::dvec2 groundPoint{0.0};      // Pg: VP->P extended to GL (2.1.1)
  glm::dvec2 picturePoint{0.0};     // Pp: Pg projected perpendicularly onto PP (2.1.2)
  glm::dvec2 cornerOnPicture{0.0};  // P1p1: P projected perpendicularly onto PP (2.1.3)
  std::optional<glm::dvec2> planPoint;  // Pa: ST->P1p1 meets Pg-Pp (2.1.3); none when P is straight below VP
  double lateralM = 0;                  // X: |Pg - GL's foot below VP| / s, signed (right positive)
  std::optional<double> depthM;         // Z from the camera: |Pa Pp| / s + f / s
};

struct SeedConstruction {
  glm::dvec2 vanishingPointPx{0.0};  // VP = ST, in the photo
  double rollDeg = 0;                // horizon angle (see vanishing.h); the image is rotated by -roll about VP
  double drawingScalePxPerM = 0;     // s
  double groundLineV = 0;            // GL: v = VP.v + s·h in the rotated image
  double picturePlaneV = 0;          // PP: v = VP.v - f in the rotated image
  std::array<glm::dvec2, kCornerCount> rotatedPx{};  // the corners in the rotated image
  // Floor corners P3, P4, P5, P6 (index corner - P3).
  std::array<SeedFloorPoint, 4> floor{};
  // Height constructions for P1 over P3, P2 over P4, P7 over P5, P8 over P6 (2.1.2):
  // Pgp, where VP->top corner meets the vertical through the floor corner's Pg.
  std::array<glm::dvec2, 4> heightPoint{};
  std::array<double, 4> heightsM{};

  // Step 4's answers: width D(P3,P4) and D(P5,P6), height D(P1,P3) ... D(P8,P6),
  // length Z(P3)-Z(P5) and Z(P4)-Z(P6), each the mean of the pairs the paper's
  // table 1 allows ("or").
  double widthM = 0;
  double heightM = 0;
  double lengthM = 0;
  // Where the camera stands: lateral offset from the corridor's centre line (x in
  // the model frame of corridor_frame.h) and distance in front of the near corners.
  double cameraXM = 0;
  double nearDepthM = 0;
};

// Runs steps 1-4 on the eight corners for a camera of focal length `focalPx` held
// `cameraHeightM` above the floor. Fails (one line) when the receding edges do not
// meet in front of the camera, a floor corner is not below the horizon, a corner
// coincides with VP, or neither corner of a pair allows the depth construction.
Result<SeedConstruction> seedConstruct(const std::array<glm::dvec2, kCornerCount>& cornersPx, double focalPx,
                                       double cameraHeightM);

}  // namespace pw::metrology
