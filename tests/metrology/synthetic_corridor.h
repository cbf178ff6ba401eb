// Synthetic corridors for the metrology tests: a known box seen by a known camera,
// projected to corners and ray-cast to a photo, so that every answer is known. The
// camera here is written from the convention corridor_frame.h states, independently
// of the code under test (no makeCameraPose, projectToPixel or rayThroughPixel), so
// that these tests check the convention, not only self-consistency.
#pragma once

#include <array>
#include <cmath>
#include <functional>

#include <glm/glm.hpp>
#include <opencv2/core.hpp>

#include "metrology/corridor_frame.h"
#include "metrology/shot.h"

namespace pw::metrology::testing {

struct SyntheticCorridor {
  double widthM = 2.4, heightM = 2.8, lengthM = 9.5;
  double cameraHeightM = 1.5, cameraXM = 0.0, cameraZM = 4.5;  // eye in the model frame
  double yawDeg = 0, pitchDeg = 0, rollDeg = 0;
  int imageWidth = 800, imageHeight = 600;
  double focalPx = 692.82;

  Intrinsics intrinsics() const { return {focalPx, principalPointPx()}; }
  glm::dvec2 principalPointPx() const { return {(imageWidth - 1) * 0.5, (imageHeight - 1) * 0.5}; }
  glm::dvec3 eyeM() const { return {cameraXM, cameraHeightM, cameraZM}; }

  // Ry(yaw) Rx(pitch) Rz(roll) applied to each column of Rz(roll): the camera's right,
  // up and back axes in the model frame. yaw > 0 turns left, pitch > 0 up.
  std::array<glm::dvec3, 3> axes() const {
    const double y = glm::radians(yawDeg), p = glm::radians(pitchDeg), r = glm::radians(rollDeg);
    auto rotate = [&](glm::dvec3 v) {
      v = {v.x, std::cos(p) * v.y - std::sin(p) * v.z, std::sin(p) * v.y + std::cos(p) * v.z};  // Rx
      return glm::dvec3(std::cos(y) * v.x + std::sin(y) * v.z, v.y, -std::sin(y) * v.x + std::cos(y) * v.z);  // Ry
    };
    return {rotate({std::cos(r), std::sin(r), 0}), rotate({-std::sin(r), std::cos(r), 0}), rotate({0, 0, 1})};
  }
  CameraPose pose() const {
    const auto [right, up, back] = axes();
    CameraPose pose;
    pose.worldFromCamera = glm::dmat3(right, up, back);
    pose.positionM = eyeM();
    pose.yawDeg = yawDeg, pose.pitchDeg = pitchDeg, pose.rollDeg = rollDeg;
    return pose;
  }
  // Pinhole projection: pixel centres at integer coordinates, u right, v down.
  glm::dvec2 project(const glm::dvec3& pointM) const {
    const auto [right, up, back] = axes();
    const glm::dvec3 d = pointM - eyeM();
    const double depth = -glm::dot(d, back);
    return principalPointPx() + focalPx * glm::dvec2(glm::dot(d, right), -glm::dot(d, up)) / depth;
  }
  // The unit ray from the eye through pixel `px`.
  glm::dvec3 ray(const glm::dvec2& px) const {
    const auto [right, up, back] = axes();
    const glm::dvec2 c = px - principalPointPx();
    return glm::normalize(right * c.x - up * c.y - back * focalPx);
  }
  // P1..P8 as corridor_frame.h lists them, written out here.
  std::array<glm::dvec3, kCornerCount> cornersM() const {
    const double w = widthM / 2, h = heightM, l = lengthM;
    return {glm::dvec3(-w, h, -l), {w, h, -l}, {-w, 0, -l}, {w, 0, -l}, {-w, 0, 0}, {w, 0, 0}, {-w, h, 0}, {w, h, 0}};
  }
  std::array<glm::dvec2, kCornerCount> cornersPx() const {
    std::array<glm::dvec2, kCornerCount> out{};
    for (int i = 0; i < kCornerCount; ++i) out[i] = project(cornersM()[i]);
    return out;
  }
  Shot shot() const {
    Shot s;
    s.imagePath = "synthetic.png";
    s.imageWidth = imageWidth;
    s.imageHeight = imageHeight;
    s.focalPx = focalPx;
    s.cameraHeightM = cameraHeightM;
    s.cornersPx = cornersPx();
    return s;
  }
};

// What a ray hits inside the box: the plane and the texture coordinates (s to the
// right, t down, both 0..1) in rectify.h's orientation, or plane < 0 for nothing.
struct Hit {
  int plane = -1;
  double s = 0, t = 0;
};

inline Hit castRay(const SyntheticCorridor& c, const glm::dvec3& origin, const glm::dvec3& d) {
  const double w2 = c.widthM / 2, h = c.heightM, l = c.lengthM;
  Hit best;
  double bestT = 1e300;
  auto consider = [&](int plane, double t, double s, double tt) {
    if (t > 1e-9 && t < bestT && s >= 0 && s <= 1 && tt >= 0 && tt <= 1) {
      bestT = t;
      best = {plane, s, tt};
    }
  };
  auto at = [&](double t) { return origin + d * t; };
  if (std::abs(d.x) > 1e-15) {
    double t = (-w2 - origin.x) / d.x;  // left wall: s from near (z=0) to far (z=-L), t from top
    glm::dvec3 p = at(t);
    consider(static_cast<int>(Plane::kLeftWall), t, -p.z / l, (h - p.y) / h);
    t = (w2 - origin.x) / d.x;  // right wall: s from far to near
    p = at(t);
    consider(static_cast<int>(Plane::kRightWall), t, (p.z + l) / l, (h - p.y) / h);
  }
  if (std::abs(d.y) > 1e-15) {
    double t = (0 - origin.y) / d.y;  // floor: top = far edge
    glm::dvec3 p = at(t);
    consider(static_cast<int>(Plane::kFloor), t, (p.x + w2) / c.widthM, (p.z + l) / l);
    t = (h - origin.y) / d.y;  // ceiling: top = near edge
    p = at(t);
    consider(static_cast<int>(Plane::kCeiling), t, (p.x + w2) / c.widthM, -p.z / l);
  }
  if (std::abs(d.z) > 1e-15) {
    const double t = (-l - origin.z) / d.z;  // far wall
    const glm::dvec3 p = at(t);
    consider(static_cast<int>(Plane::kFarWall), t, (p.x + w2) / c.widthM, (h - p.y) / h);
  }
  return best;
}

// Renders the corridor, `shade` giving each hit's BGR colour; `supersample`^2 rays
// a pixel, averaged (what a camera's pixel does).
inline cv::Mat renderCorridor(const SyntheticCorridor& c, const std::function<cv::Vec3d(const Hit&)>& shade,
                              int supersample = 1) {
  cv::Mat image(c.imageHeight, c.imageWidth, CV_8UC3);
  cv::parallel_for_(cv::Range(0, c.imageHeight), [&](const cv::Range& rows) {
    for (int v = rows.start; v < rows.end; ++v) {
      for (int u = 0; u < c.imageWidth; ++u) {
        cv::Vec3d sum(0, 0, 0);
        for (int j = 0; j < supersample; ++j) {
          for (int i = 0; i < supersample; ++i) {
            const glm::dvec2 px(u - 0.5 + (i + 0.5) / supersample, v - 0.5 + (j + 0.5) / supersample);
            const Hit hit = castRay(c, c.eyeM(), c.ray(px));
            sum += hit.plane < 0 ? cv::Vec3d(128, 128, 128) : shade(hit);
          }
        }
        sum *= 1.0 / (supersample * supersample);
        image.at<cv::Vec3b>(v, u) = cv::Vec3b(cv::saturate_cast<uchar>(sum[0]), cv::saturate_cast<uchar>(sum[1]),
                                              cv::saturate_cast<uchar>(sum[2]));
      }
    }
  });
  return image;
}

}  // namespace pw::metrology::testing
