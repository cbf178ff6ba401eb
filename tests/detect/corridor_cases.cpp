#include "tests/detect/corridor_cases.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include <opencv2/imgcodecs.hpp>

#include "tests/support/groundtruth.h"

namespace pw::metrology::detect::testing {

namespace {
glm::dvec2 leastSquaresMeet(const std::vector<std::pair<glm::dvec2, glm::dvec2>>& lines) {
  // Minimise sum (n·x - c)^2 over unit normals n of each line.
  double a11 = 0, a12 = 0, a22 = 0, b1 = 0, b2 = 0;
  for (auto [p, q] : lines) {
    const glm::dvec2 d = glm::normalize(q - p);
    const glm::dvec2 n(-d.y, d.x);
    const double c = glm::dot(n, p);
    a11 += n.x * n.x, a12 += n.x * n.y, a22 += n.y * n.y, b1 += n.x * c, b2 += n.y * c;
  }
  const double det = a11 * a22 - a12 * a12;
  return {(b1 * a22 - b2 * a12) / det, (a11 * b2 - a12 * b1) / det};
}
}  // namespace

std::vector<CorridorCase> loadCorridorCases() { return loadCorridorCases(pw::groundtruth::groundTruthNames()); }

std::vector<CorridorCase> loadCorridorCases(const std::vector<std::string>& names) {
  std::vector<CorridorCase> cases;
  for (const std::string& name : names) {
    const pw::groundtruth::GroundTruth g = pw::groundtruth::loadGroundTruth(name);
    CorridorCase c;
    c.name = g.name;
    c.imagePath = g.image.string();
    c.image = cv::imread(c.imagePath, cv::IMREAD_COLOR);
    if (c.image.empty()) throw std::runtime_error("cannot read " + c.imagePath);
    c.focalPx = g.focalPx;
    c.principalPoint = g.principalPointPx;
    c.cameraHeightM = g.cameraHeightM;
    c.widthM = g.widthM, c.heightM = g.heightM, c.lengthM = g.lengthM;
    c.corners = g.cornersPx;
    c.vanishingPoint = leastSquaresMeet({{c.corners[0], c.corners[6]}, {c.corners[1], c.corners[7]},
                                         {c.corners[2], c.corners[4]}, {c.corners[3], c.corners[5]}});
    cases.push_back(std::move(c));
  }
  return cases;
}

double medianOf(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace pw::metrology::detect::testing
