// A shot: one photo, the camera that took it, and the corridor's eight corners in it.
//
// Corner names follow the seed paper's table 1 (see ../shared/METHOD.md):
//   P1 P2  far wall top-left / top-right      P3 P4  far wall bottom-left / bottom-right
//   P5 P6  floor near-left / near-right       P7 P8  ceiling near-left / near-right
// Pixel coordinates: origin at the centre of the top-left pixel, u right, v down.
#pragma once

#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "metrology/distortion.h"

namespace pw::metrology {

enum Corner : int { P1 = 0, P2, P3, P4, P5, P6, P7, P8 };
inline constexpr int kCornerCount = 8;
inline const char* cornerName(int corner) {
  static const char* const kNames[kCornerCount] = {"P1", "P2", "P3", "P4", "P5", "P6", "P7", "P8"};
  return (corner >= 0 && corner < kCornerCount) ? kNames[corner] : "P?";
}

// The five planes of a corridor, each as four corners in order around the quad
// (the order the seed paper gives: the rectified texture's top-left, top-right,
// bottom-right, bottom-left as seen from inside the corridor).
enum class Plane : int { kFarWall = 0, kLeftWall, kRightWall, kFloor, kCeiling };
inline constexpr int kPlaneCount = 5;
inline constexpr std::array<std::array<int, 4>, kPlaneCount> kPlaneCorners{{
    {P1, P2, P4, P3},  // far wall
    {P7, P1, P3, P5},  // left wall
    {P2, P8, P6, P4},  // right wall
    {P3, P4, P6, P5},  // floor
    {P7, P8, P2, P1},  // ceiling
}};
inline const char* planeName(Plane plane) {
  static const char* const kNames[kPlaneCount] = {"far_wall", "left_wall", "right_wall", "floor", "ceiling"};
  return kNames[static_cast<int>(plane)];
}

// Two corners whose true distance is known: fixes the scale instead of (or as a
// check on) the camera height.
struct ReferenceLength {
  int from = P3;
  int to = P4;
  double lengthM = 0;
  bool operator==(const ReferenceLength&) const = default;
};

struct FocalLengthMm {
  double focalMm = 0;
  double sensorWidthMm = 0;
  double pixels(int imageWidth) const { return focalMm / sensorWidthMm * imageWidth; }
  bool operator==(const FocalLengthMm&) const = default;
};

// Points on objects in the photo and what to measure between them (object_measure.h
// places and measures them; README "Measuring objects").
enum class PointSurface { kFloor, kCeiling, kLeftWall, kRightWall, kFarWall, kAbove };
// "floor", "ceiling", "wall:left", "wall:right", "wall:far", "above:NAME" (the name apart).
std::string surfaceName(PointSurface surface);
// From those words; nullopt for anything else. `above` receives NAME for "above:NAME".
std::optional<PointSurface> surfaceFromName(const std::string& text, std::string* above);

struct PointOn {
  PointSurface surface = PointSurface::kFloor;
  std::string above;  // for kAbove: the point this one stands above (listed before it)
  bool operator==(const PointOn&) const = default;
};

struct ImagePoint {
  std::string name;
  glm::dvec2 px{0.0};  // where the photo shows it (through its lens)
  PointOn on;
  bool operator==(const ImagePoint&) const = default;
};

// What is measured between two named points.
enum class ObjectQuantity {
  kDistance,  // |B - A|
  kHeight,    // B.y - A.y: how far B is above A
};
const char* quantityName(ObjectQuantity quantity);

struct ObjectMeasure {
  ObjectQuantity quantity = ObjectQuantity::kDistance;
  std::string from, to;
  std::string name;  // what a person calls it ("door width"); may be empty
  bool operator==(const ObjectMeasure&) const = default;
};

// An object in the photo to stand up in the model (`build`; modeling/stand_up.h): the
// outline a person drew around it, which need not be tight (GrabCut finds the object
// inside it), down to where it stands on the floor. Flat: one upright cut-out facing the
// photo's camera (a person, a plant); a box: a box standing on the floor, its sides along
// the corridor's axes (a cabinet, a bench, a radiator). Hanging: a flat cut-out hanging
// from the ceiling where the outline's top meets it (a lamp on a rod, a sign), drawn
// up to where it hangs instead of down to a foot. An opening is no object: a
// doorway or an opening into a room in a side wall, opened in the model with a room
// behind it (modeling/side_room.h).
enum class CutoutShape { kFlat, kBox, kOpening, kHanging };

struct Cutout {
  std::string name;
  std::vector<glm::dvec2> outlinePx;  // a polygon of 3 or more photo pixels (a rectangle: 4)
  CutoutShape shape = CutoutShape::kFlat;
  bool operator==(const Cutout&) const = default;
};

struct Shot {
  std::string imagePath;  // as resolved for opening (relative to the shot file's folder)
  int imageWidth = 0;     // filled from the image when it is loaded
  int imageHeight = 0;
  double focalPx = 0;
  // The focal length as the user gave it, in millimetres with the sensor's width: then
  // focalPx = focalMm / sensorWidthMm * imageWidth once the image is known (shot files
  // keep it in these units when written back).
  std::optional<FocalLengthMm> focalMm;
  std::optional<glm::dvec2> principalPointPx;  // default: ((w-1)/2, (h-1)/2)
  std::optional<double> cameraHeightM;
  std::array<glm::dvec2, kCornerCount> cornersPx{};
  std::optional<ReferenceLength> reference;
  // The lens's radial distortion (distortion.h); the corners are where the photo shows
  // them. Unset: not known (measure may estimate it from the corners, measure.h); set
  // to zero: known to be none.
  std::optional<RadialDistortion> distortion;
  // Named points on objects in the photo and the distances and heights asked between
  // them (the shot file's "points" and "measurements").
  std::vector<ImagePoint> points;
  std::vector<ObjectMeasure> measurements;
  // Objects to stand up in the model (the shot file's "cutouts").
  std::vector<Cutout> cutouts;

  // Every field, the distortion and the points included (an edit of any of them is an edit).
  bool operator==(const Shot&) const = default;

  glm::dvec2 principalPoint() const {
    return principalPointPx.value_or(glm::dvec2((imageWidth - 1) * 0.5, (imageHeight - 1) * 0.5));
  }
  // Whether the principal point is away from the photo's centre: given, and more than
  // a hundredth of a pixel off it (a shot file may write the centre itself, as the
  // sample's does).
  bool principalPointMoved() const {
    if (!principalPointPx) return false;
    const glm::dvec2 off = *principalPointPx - glm::dvec2((imageWidth - 1) * 0.5, (imageHeight - 1) * 0.5);
    return std::abs(off.x) > 0.01 || std::abs(off.y) > 0.01;
  }
};

}  // namespace pw::metrology
