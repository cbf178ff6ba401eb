// Synthetic corridors for the metrology tests: a known box seen by a known camera,
// projected to corners and ray-cast to a photo, so that every answer is known.
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

  Intrinsics intrinsics() const { return {focalPx, {(imageWidth - 1) * 0.5, (imageHeight - 1) * 0.5}}; }
  CameraPose pose() const {
    return makeCameraPose(yawDeg, pitchDeg, rollDeg, glm::dvec3(cameraXM, cameraHeightM, cameraZM));
  }
  std::array<glm::dvec2, kCornerCount> cornersPx() const {
    const auto corners = corridorCorners(widthM, heightM, lengthM);
    std::array<glm::dvec2, kCornerCount> out{};
    for (int i = 0; i < kCornerCount; ++i) out[i] = glm::dvec2(projectToPixel(intrinsics(), pose(), corners[i]));
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
  const Intrinsics k = c.intrinsics();
  const CameraPose pose = c.pose();
  cv::parallel_for_(cv::Range(0, c.imageHeight), [&](const cv::Range& rows) {
    for (int v = rows.start; v < rows.end; ++v) {
      for (int u = 0; u < c.imageWidth; ++u) {
        cv::Vec3d sum(0, 0, 0);
        for (int j = 0; j < supersample; ++j) {
          for (int i = 0; i < supersample; ++i) {
            const glm::dvec2 px(u - 0.5 + (i + 0.5) / supersample, v - 0.5 + (j + 0.5) / supersample);
            const Hit hit = castRay(c, pose.positionM, rayThroughPixel(k, pose.worldFromCamera, px));
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
