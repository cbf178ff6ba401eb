// A baseline for bench/york_urban_bench (not the product): the Manhattan frame by
// Xiaohu Lu, Jian Yao, Haoang Li, Yahui Liu, Xiaofeng Zhang, "2-Line Exhaustive
// Searching for Real-Time Vanishing Point Estimation in Manhattan World", WACV 2017,
// written here from the paper (and read against the authors' public code,
// github.com/xiaohulugo/VanishingPointDetection, for its constants):
//
//   lines      LSD (OpenCV's, the paper's detector) segments longer than 30 px;
//   hypotheses the first direction v1 from two lines drawn at random, as many draws as
//              RANSAC needs for 0.9999 confidence with half the lines outliers
//              (p = (1 - 0.5)^2 / 3: 105 draws); for each v1 the second v2 at 360 steps
//              of 1 degree around the great circle orthogonal to v1; v3 = v1 x v2;
//   scoring    a polar grid over the half sphere in front of the camera (90 latitude x
//              360 longitude bins of 1 degree) accumulating every pair of lines'
//              intersection, weighted sqrt(l_i l_j) (sin 2θ + 0.2) (θ the angle between
//              the two lines in the image; pairs more than 60 degrees apart skipped),
//              then smoothed by adding each bin's 3x3 neighbourhood mean; a hypothesis
//              scores the sum of its three directions' bins; the best one wins, with no
//              refinement after it.
//
// Differences from the authors' code, none of them in the method: a fixed random seed
// (the same photo always gives the same answer), and the smoothing wraps around in
// longitude and clamps at the grid's latitude edges (the code leaves the border bins
// at zero, so a vanishing point within a degree of the principal point could not win).
#pragma once

#include <array>
#include <vector>

#include <glm/glm.hpp>
#include <opencv2/core/mat.hpp>

namespace pw::bench::lu {

struct Line {
  glm::dvec2 a, b;
  double lengthPx = 0;
};

// The paper's segments: LSD on the gray photo, those longer than `minLengthPx` (30).
std::vector<Line> detectLines(const cv::Mat& gray, double minLengthPx = 30.0);

struct Frame {
  bool found = false;
  std::array<glm::dvec3, 3> directions{};  // unit, camera coordinates (x right, y down, z forward)
  double score = 0;                        // the polar grid's response of the winner
};

// The frame with the camera given.
Frame estimateFrame(const std::vector<Line>& lines, double focalPx, glm::dvec2 principalPointPx);

// With the focal length withheld: the frame found with f = the long side (the authors'
// suggestion for an unknown camera); each point then fitted in the image to its own
// lines (those within 6 degrees of pointing at it, the authors' clustering: least-squares
// intersection), f from the two nearest the principal point, f^2 = -(v1 - c).(v2 - c)
// (Hartley & Zisserman 8.8.1), and the frame found again with it, until f settles
// (0.5%); f stays where no two finite points fix it. (A grid of focal lengths picking
// the best-scoring frame was tried first: the polar grid's score does not pin f down,
// its winners sat at either end of the grid, 49% off in the median on York Urban.)
struct FocalSearch {
  double focalPx = 0;
  Frame frame;
};
FocalSearch estimateFrameAndFocal(const std::vector<Line>& lines, glm::dvec2 principalPointPx, cv::Size imageSize);

}  // namespace pw::bench::lu
