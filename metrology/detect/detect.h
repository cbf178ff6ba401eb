// Automatic corridor detection (issue 7): from one photo, the corridor's vanishing
// points and its eight corners P1..P8 (../shared/METHOD.md names them), each with a
// confidence, ready to be written as a shot file and adjusted in the editor.
//
// Pipeline (each step in its own file):
//   working_image     a copy shrunk by a whole factor to a long side <= 1280 px
//   line_segments     LSD segments on it, in parallel bands
//   vanishing_points  Manhattan frame by RANSAC on the Gaussian sphere, per-direction
//                     least squares; focal length from two finite points, or given
//   boundaries        the four receding boundaries from the angular profile around
//                     the corridor vanishing point
//   cross_sections    the far wall as the cross-section where the boundaries begin;
//                     a marked cross-section (band, frame) nearer the camera
//   room_box          when that fails or leaves doubts (clutter hides boundaries):
//                     the far wall from the room's box fitted to all the edges at
//                     once, in the photo rectified by the horizontal and vertical
//                     points
//   edge_fit          every side and boundary refitted at full resolution to
//                     sub-pixel precision; corners as intersections of fitted lines;
//                     the boundaries then run through the fitted far-wall corners;
//                     the doubts: thin evidence for the box (CorridorDetection)
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <opencv2/core/mat.hpp>

#include "base/result.h"
#include "metrology/detect/vanishing_points.h"
#include "metrology/distortion.h"

namespace pw::metrology::detect {

struct DetectOptions {
  std::optional<double> focalPx;               // withheld: estimated, else a default with a warning
  std::optional<glm::dvec2> principalPointPx;  // default: the image centre ((w-1)/2, (h-1)/2)
  int workingMaxSidePx = 1280;                 // detection runs on a copy no larger than this
  // P5..P8 on a marked cross-section (a band painted or a frame built across the
  // corridor, looked for between the far wall and the camera) when one is found. Off by
  // default: real corridors have no such band, and a door frame, a lamp's light or a
  // change of floor tiles passes for one (P5..P8 then a metre before the far wall);
  // P5..P8 then go to the nearest cross-section whose four corners lie inside the
  // photo (near_depth image_edge), as ../shared/METHOD.md's convention has it.
  bool nearAtMarkedCrossSection = false;
  // Fit the lens's radial distortion to the photo's straight lines (distortion.h) and,
  // when they show one, detect on the photo undistorted.
  bool estimateDistortion = true;
  // The lens when it is known (a calibrated camera, or the distortion a shot file
  // carries: normalised by the focal length given, else by the one detection uses):
  // detection reads the photo through it and fits none of its own; {0, 0} is a known
  // pinhole. It wins over estimateDistortion.
  std::optional<RadialDistortion> lens;
  // Corners a person placed roughly (the photo's pixels, P1..P8): instead of searching
  // the whole photo, detection fits them to its edges and vanishing points, each side
  // and boundary looked for within hintReachPx of where they were put. P5..P8 keep the
  // depth they were given (on the fitted boundaries), or go to the nearest depth inside
  // the photo when they were put within reach of it.
  std::optional<std::array<glm::dvec2, 8>> hintPx;
  double hintReachPx = 25;
  // false: the hint's P5..P8 only point out the receding boundaries, and go to the
  // nearest depth inside the photo wherever they were put.
  bool hintNearDepthGiven = true;
  // With a hint: detection's own answer is looked for too, and may take the fit's place
  // where its far corners lie within reach of the hint's (detect.cpp: fitRoughBox).
  // false: the hint's fit alone (the editor's snap of one corner, which has to be quick).
  bool hintWeighsDetection = true;
};

enum class FocalSource { kGiven, kVanishingPoints, kDefault };
enum class NearDepth { kMarkedCrossSection, kImageEdge, kGiven };
const char* focalSourceName(FocalSource source);
const char* nearDepthName(NearDepth depth);

// Default focal length when none is given and the photo has no second finite
// vanishing point: a 28 mm-equivalent lens (28/36 of the long side, rounded to 0.8),
// typical of phone cameras.
inline constexpr double kDefaultFocalOverLongSide = 0.8;

struct CornerEstimate {
  glm::dvec2 px{0, 0};
  double confidence = 0;  // 0..1: edge coverage of the lines that meet there, less for a poor fit
  double sigmaPx = 0;     // 1-sigma position uncertainty from the line fits
};

struct CorridorDetection {
  bool found = false;
  std::string notFoundReason;  // one line when !found: why this is not a corridor photo
  // The Manhattan frame was found (corridor, horizontal and vertical below are set),
  // whether or not a corridor's box was: a person or the editor can still use them.
  bool hasVanishingPoints = false;

  double focalPx = 0;
  FocalSource focalSource = FocalSource::kGiven;
  glm::dvec2 principalPointPx{0, 0};
  VanishingPoint corridor, horizontal, vertical;  // full-resolution pixels
  std::array<CornerEstimate, 8> corners{};        // P1..P8
  NearDepth nearDepth = NearDepth::kImageEdge;
  // found and sure of it: every check of the corridor's box passed. A found corridor
  // that is not confident is a best guess for a person to check (detect exits 3);
  // `doubts` says, one line each, what made it unsure.
  bool confident = false;
  std::vector<std::string> doubts;
  std::vector<std::string> warnings;
  int segmentCount = 0;
  // The lens's radial distortion (normalised by focalPx): the one given
  // (DetectOptions::lens), else the one found from the photo's straight lines; none: a
  // pinhole photo. The corners are the photo's pixels, the vanishing points the
  // undistorted image's.
  RadialDistortion distortion;
  int plumbLineCount = 0;  // the straight lines it was fitted to; 0 where the lens was given
  // A rough box's fit (hintPx): a receding boundary did not show near the line put
  // through it (a white ceiling meeting white walls), so the far wall's sides were
  // fitted first, each near where it was put.
  bool hintBoundaryUnseen = false;
};

// Finds the corridor in `photoBgr` (CV_8UC3, any size). The error is for input a
// person must fix (empty image, a focal length or principal point that makes no
// sense); a photo that simply shows no corridor comes back with found == false and
// the reason. A sure answer's corners lie on fitted image edges or, for P5..P8 without a
// marked cross-section, on fitted boundaries at the stated depth; an unsure one's may be
// a person's rough box or the layout network's (layout_net.h) as they were put, with
// confidence 0 and a doubt saying so.
Result<CorridorDetection> detectCorridor(const cv::Mat& photoBgr, const DetectOptions& options);

// The far wall's (P1..P4) width over its height in the corridor: it stands square to the
// corridor's direction, so its corners cast from the camera onto any plane square to that
// direction (the focal length and principal point of `detection`) keep its shape.
// Detection takes no far wall beyond 6 or under 1/6: a corridor's end is not a sliver.
double farWallAspect(const CorridorDetection& detection);

// A starting box for a person to drag where detection found the vanishing points but
// no box: the far wall a rectangle around the corridor's vanishing point (a fifth of
// the photo's short side), its sides pointing at the horizontal and vertical points,
// and P5..P8 at the nearest depth inside the photo; so every line of it already
// recedes as the photo's do. nullopt without vanishing points, or when the corridor's
// lies outside the photo.
std::optional<std::array<glm::dvec2, 8>> boxAlongVanishingPoints(const CorridorDetection& detection, cv::Size size);

}  // namespace pw::metrology::detect
