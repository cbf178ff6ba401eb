// The room's layout seen by two small convolutional networks: each pixel as the far
// wall, the left or right wall, the floor or the ceiling of the room's box, and the box
// fitted to that map; first on the whole photo (shrunk to a 192 px long side,
// assets/models/layout_net.onnx), then on the far wall's neighbourhood zoomed to 192 x
// 192 (layout_zoom_net.onnx). Both are built into the program and were trained by
// scripts/train_layout_net.py on the random scenes' TUNE seeds only. Each is given the
// photo and, per pixel, where its ray points in the corridor's frame (from the vanishing
// points), so it only has to say where the box's sides are. They see the room's layout
// behind a person or a cabinet, where the edges do not show, to a few pixels on scenes
// like those they learnt from, and can be tens of pixels off on others (a door at the far
// end taken for the far wall): detection uses the box to confirm an answer of the
// edges, as a person's rough box to be fitted to the edges where those found none, and,
// where that fit fails too, as an unsure guess of its own, in place of an unsure answer
// of the edges whose far wall it finds far less likely than its own box (boxScore;
// detect.cpp: findCorridor, layoutGuess and layoutOverEdges), and, the whole photo's look
// alone, to tell a sure answer's far wall from a far wall and its reflection in a glossy
// floor (lookAtWholePhoto; detect.cpp: unreflectedSure).
#pragma once

#include <array>
#include <memory>
#include <optional>

#include <glm/glm.hpp>
#include <opencv2/core/mat.hpp>

namespace pw::metrology::detect {

// The corridor's frame in the pinhole camera's (x right, y down, z forward; unit
// vectors): across the corridor to the right, up, and along it away from the camera.
struct CorridorAxes {
  glm::dvec3 right, up, away;
};

// The frame from the three vanishing points (homogeneous full-resolution pixels, at
// infinity or not) of a camera with `focalPx` and `principalPx`.
CorridorAxes corridorAxes(glm::dvec3 horizontal, glm::dvec3 vertical, glm::dvec3 corridor, double focalPx,
                          glm::dvec2 principalPx);

struct LayoutFit {
  // The far wall's sides where a ray's point one unit along `away` lies: the far plane's
  // coordinates (left < right along `right`, bottom < top along `up`).
  double left = 0, right = 0, bottom = 0, top = 0;
  // The mean log-probability the network gives the box's labels, per pixel (0 at best).
  double score = 0;
  // The same for the whole photo's box (before the zoomed look): how much the photo
  // looks like a room's box to the network. On the random scenes it did not learn from
  // (seeds 600-1399) it is above -0.25 in 98% of the rooms, above -0.29 in 99%; on the
  // tests' drawn road and outdoor scene and on camera.png -0.47 to -0.74; on York Urban's
  // streets, lined by buildings like a corridor's walls, as high as -0.19.
  double wholeScore = 0;
  // What the networks saw (for boxScore).
  std::shared_ptr<const struct LayoutLooks> looks;
};

// The mean log-probability per pixel of the labels that the box with far corners
// `farPx` (P1..P4, full-resolution pixels) gives, in the whole photo's look (`zoomed`
// false) or the far wall's neighbourhood's.
std::optional<double> boxScore(const LayoutFit& fit, const std::array<glm::dvec2, 4>& farPx, double focalPx,
                               glm::dvec2 principalPx, const CorridorAxes& axes, bool zoomed);

// The layout of `bgr` (CV_8UC3, any size: the photo scaled by `workScale`, pixel centres mapping as WorkingImage's do, to the
// photo's full-resolution pixels, in which `focalPx` and `principalPx` are given).
// nullopt when the network finds no far wall around the vanishing point.
std::optional<LayoutFit> fitLayout(const cv::Mat& bgr, double workScale, double focalPx, glm::dvec2 principalPx,
                                   const CorridorAxes& axes);

// The whole photo's look alone, about half fitLayout's work: no box fitted (the fit's
// sides and scores are 0), no neighbourhood looked at; for boxScore's whole-photo score
// (`zoomed` false) of boxes found otherwise. nullopt where the network cannot run.
std::optional<LayoutFit> lookAtWholePhoto(const cv::Mat& bgr, double workScale, double focalPx, glm::dvec2 principalPx,
                                          const CorridorAxes& axes);

// P1..P4 of `fit` (full-resolution pixels), and P5..P8 at the nearest cross-section
// whose four corners lie `marginPx` inside a photo of `size` (nullopt when none does).
std::optional<std::array<glm::dvec2, 8>> layoutCorners(const LayoutFit& fit, double focalPx, glm::dvec2 principalPx,
                                                       const CorridorAxes& axes, cv::Size size, double marginPx);

}  // namespace pw::metrology::detect
