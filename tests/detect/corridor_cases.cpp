#include "tests/detect/corridor_cases.h"

#include <algorithm>
#include <filesystem>
#include <fstream>

#include <opencv2/imgcodecs.hpp>

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

std::vector<CorridorCase> loadCorridorCases() {
  std::vector<CorridorCase> cases;
  const std::filesystem::path dir = std::filesystem::path(PW_SHARED_DIR) / "corridors";
  for (const char* name : {"corridor_a", "corridor_b", "corridor_c", "corridor_d", "corridor_e"}) {
    std::ifstream in(dir / (std::string(name) + ".json"));
    if (!in) continue;
    const nlohmann::json gt = nlohmann::json::parse(in);
    CorridorCase c;
    c.name = name;
    c.imagePath = (dir / gt["image"].get<std::string>()).string();
    c.image = cv::imread(c.imagePath, cv::IMREAD_COLOR);
    if (c.image.empty()) continue;
    c.focalPx = gt["focal_px"];
    c.principalPoint = {gt["principal_point"][0], gt["principal_point"][1]};
    c.cameraHeightM = gt["camera_height_m"];
    c.widthM = gt["width_m"], c.heightM = gt["height_m"], c.lengthM = gt["length_m"];
    for (int k = 0; k < 8; ++k) {
      const auto& p = gt["corners_px"]["P" + std::to_string(k + 1)];
      c.corners[k] = {p[0], p[1]};
    }
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
