// The ground-truth POV-Ray corridors (tests/support/groundtruth.h) as detection
// cases, with their photos loaded.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>
#include <opencv2/core/mat.hpp>

namespace pw::metrology::detect::testing {

struct CorridorCase {
  std::string name;
  std::string imagePath;
  cv::Mat image;
  double focalPx = 0;
  glm::dvec2 principalPoint{0, 0};
  double cameraHeightM = 0;
  double widthM = 0, heightM = 0, lengthM = 0;
  std::array<glm::dvec2, 8> corners{};  // P1..P8
  // Least-squares meeting point of the four receding ground-truth edges P1-P7,
  // P2-P8, P3-P5, P4-P6.
  glm::dvec2 vanishingPoint{0, 0};
};

// Throws when a scene is missing. The clean corridors a-h, or the scenes named.
std::vector<CorridorCase> loadCorridorCases();
std::vector<CorridorCase> loadCorridorCases(const std::vector<std::string>& names);

double medianOf(std::vector<double> values);

}  // namespace pw::metrology::detect::testing
