#include "tests/detect/synthetic_corridor.h"

#include <cmath>
#include <limits>
#include <random>

#include <glm/gtc/matrix_transform.hpp>
#include <opencv2/imgproc.hpp>

namespace pw::metrology::detect::testing {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Camera to world: roll about the view axis, then pitch, then yaw (world: x right,
// y up, z along the corridor; camera: x right, y up, z forward).
glm::dmat3 cameraToWorld(const CorridorSpec& s) {
  const double y = s.yawDeg * kPi / 180, p = s.pitchDeg * kPi / 180, r = s.rollDeg * kPi / 180;
  const glm::dmat3 yaw(std::cos(y), 0, -std::sin(y), 0, 1, 0, std::sin(y), 0, std::cos(y));
  const glm::dmat3 pitch(1, 0, 0, 0, std::cos(p), std::sin(p), 0, -std::sin(p), std::cos(p));
  const glm::dmat3 roll(std::cos(r), std::sin(r), 0, -std::sin(r), std::cos(r), 0, 0, 0, 1);
  return yaw * pitch * roll;
}

glm::dvec3 shade(const CorridorSpec& s, glm::dvec3 origin, glm::dvec3 dir) {
  const double halfW = s.corridorWidthM / 2;
  double best = std::numeric_limits<double>::infinity();
  int plane = -1;
  const auto consider = [&](double t, int id) {
    if (!(t > 1e-9) || t >= best) return;
    const glm::dvec3 p = origin + t * dir;
    const double eps = 1e-9;
    if (p.x < -halfW - eps || p.x > halfW + eps || p.y < -eps || p.y > s.corridorHeightM + eps || p.z > s.farWallM + eps)
      return;
    best = t, plane = id;
  };
  if (dir.x != 0) consider((-halfW - origin.x) / dir.x, 0), consider((halfW - origin.x) / dir.x, 1);
  if (dir.y != 0) consider((0 - origin.y) / dir.y, 2), consider((s.corridorHeightM - origin.y) / dir.y, 3);
  if (dir.z != 0) consider((s.farWallM - origin.z) / dir.z, 4);
  if (plane < 0) return {0, 0, 0};
  const glm::dvec3 p = origin + best * dir;
  switch (plane) {
    case 0: case 1: return {190, 205, 215};          // walls (BGR): warm light grey
    case 2: {                                        // floor: 0.5 m tiles
      const bool dark = (static_cast<int>(std::floor(p.x / 0.5)) + static_cast<int>(std::floor(p.z / 0.5))) & 1;
      return dark ? glm::dvec3(90, 80, 75) : glm::dvec3(170, 175, 180);
    }
    case 3: return {140, 140, 140};                  // ceiling
    default: {                                       // far wall with a door
      const bool door = std::abs(p.x) < 0.45 && p.y < 2.0;
      return door ? glm::dvec3(40, 80, 120) : glm::dvec3(150, 180, 160);
    }
  }
}

}  // namespace

SyntheticCorridor renderCorridor(const CorridorSpec& s) {
  SyntheticCorridor out;
  out.principalPoint = glm::dvec2((s.widthPx - 1) * 0.5, (s.heightPx - 1) * 0.5);
  const glm::dmat3 r = cameraToWorld(s);
  const glm::dvec3 camera(s.cameraXM, s.cameraHeightM, 0);
  const glm::dvec2 c = out.principalPoint;
  out.image.create(s.heightPx, s.widthPx, CV_8UC3);
  std::mt19937 rng(99);
  std::normal_distribution<double> noise(0.0, s.noiseSigma);
  for (int v = 0; v < s.heightPx; ++v) {
    for (int u = 0; u < s.widthPx; ++u) {
      glm::dvec3 sum(0);
      for (int sy = 0; sy < 2; ++sy)
        for (int sx = 0; sx < 2; ++sx) {
          const double pu = u - 0.25 + 0.5 * sx, pv = v - 0.25 + 0.5 * sy;
          const glm::dvec3 ray = r * glm::dvec3((pu - c.x) / s.focalPx, -(pv - c.y) / s.focalPx, 1.0);
          sum += shade(s, camera, glm::normalize(ray));
        }
      cv::Vec3b& px = out.image.at<cv::Vec3b>(v, u);
      for (int k = 0; k < 3; ++k) px[k] = cv::saturate_cast<uchar>(sum[k] / 4 + noise(rng));
    }
  }
  const auto project = [&](glm::dvec3 world) {
    const glm::dvec3 pc = glm::transpose(r) * (world - camera);
    return glm::dvec2(c.x + s.focalPx * pc.x / pc.z, c.y - s.focalPx * pc.y / pc.z);
  };
  const double halfW = s.corridorWidthM / 2;
  out.farWall = {project({-halfW, s.corridorHeightM, s.farWallM}), project({halfW, s.corridorHeightM, s.farWallM}),
                 project({-halfW, 0, s.farWallM}), project({halfW, 0, s.farWallM})};
  const glm::dvec3 d = glm::transpose(r) * glm::dvec3(0, 0, 1);
  out.vanishingPoint = glm::dvec2(c.x + s.focalPx * d.x / d.z, c.y - s.focalPx * d.y / d.z);
  return out;
}

// Sky, a horizon, grass, trees (trunks and crowns), a house with a roof, noise.
cv::Mat drawOutdoorScene(unsigned seed) {
  cv::Mat o(600, 800, CV_8UC3);
  for (int y = 0; y < 600; ++y)
    for (int x = 0; x < 800; ++x)
      o.at<cv::Vec3b>(y, x) = y < 260 ? cv::Vec3b(230 - y / 4, 190 - y / 6, 140 - y / 8) : cv::Vec3b(60, 120 + (y - 260) / 8, 70);
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> xs(0, 800), sizes(20, 60);
  for (int i = 0; i < 9; ++i) {
    const int x = xs(rng), s = sizes(rng), base = 260 + 2 * s;
    cv::rectangle(o, cv::Rect(x - s / 6, base - 3 * s, s / 3, 3 * s), cv::Scalar(30, 60, 90), cv::FILLED);
    cv::circle(o, {x, base - 3 * s}, s, cv::Scalar(40, 110 + s, 50), cv::FILLED);
  }
  cv::rectangle(o, cv::Rect(520, 180, 160, 110), cv::Scalar(90, 110, 180), cv::FILLED);
  const std::vector<cv::Point> roof = {{510, 180}, {600, 120}, {690, 180}};
  cv::fillConvexPoly(o, roof, cv::Scalar(40, 40, 120));
  cv::Mat noise(o.size(), CV_8UC3);
  cv::randn(noise, 0, 12);
  cv::add(o, noise, o);
  return o;
}

// The hardest outdoor case for a corridor detector: a straight road whose edges and
// centre line converge to a vanishing point on the horizon, with verges and sky.
cv::Mat drawRoadScene() {
  cv::Mat o = drawOutdoorScene(11);
  const cv::Point vp = kRoadVanishingPoint;
  const std::vector<cv::Point> road = {vp, {40, 599}, {760, 599}};
  cv::fillConvexPoly(o, road, cv::Scalar(70, 70, 75), cv::LINE_AA);
  cv::line(o, vp, {400, 599}, cv::Scalar(240, 240, 240), 3, cv::LINE_AA);
  cv::line(o, vp, {120, 599}, cv::Scalar(220, 220, 220), 2, cv::LINE_AA);
  cv::line(o, vp, {680, 599}, cv::Scalar(220, 220, 220), 2, cv::LINE_AA);
  return o;
}

}  // namespace pw::metrology::detect::testing
