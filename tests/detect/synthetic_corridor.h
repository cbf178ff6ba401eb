// Synthetic corridor photos with exact answers, for any camera rotation: a box
// corridor ray-cast pixel by pixel (2x2 supersampled), tiled floor, plain walls
// and ceiling, a far wall with a door. The ground truth's POV-Ray scenes a-e look straight
// down the corridor; these turn the camera.
#pragma once

#include <array>

#include <glm/glm.hpp>
#include <opencv2/core/mat.hpp>
#include <opencv2/core/types.hpp>

namespace pw::metrology::detect::testing {

struct CorridorSpec {
  int widthPx = 800, heightPx = 600;
  double focalPx = 700;
  double corridorWidthM = 2.4, corridorHeightM = 2.8, farWallM = 12.0;
  double cameraHeightM = 1.5, cameraXM = 0.0;
  double yawDeg = 0, pitchDeg = 0, rollDeg = 0;
  double noiseSigma = 3.0;  // grey levels
};

struct SyntheticCorridor {
  cv::Mat image;                      // CV_8UC3
  std::array<glm::dvec2, 4> farWall;  // P1 P2 P3 P4, pixels
  glm::dvec2 vanishingPoint;          // of the corridor direction
  glm::dvec2 principalPoint;
};

SyntheticCorridor renderCorridor(const CorridorSpec& spec);

// Photos that are not corridors, 800x600: sky, a horizon, grass, trees, a house, noise;
// and the same with a straight road converging to kRoadVanishingPoint on the horizon.
cv::Mat drawOutdoorScene(unsigned seed);
inline const cv::Point kRoadVanishingPoint(400, 260);
cv::Mat drawRoadScene();

}  // namespace pw::metrology::detect::testing
