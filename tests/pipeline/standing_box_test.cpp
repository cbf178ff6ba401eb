// Box-like objects stood up as boxes (issue 25, part 3): cabinets of known size in a
// synthetic corridor seen turned and tilted (tests/metrology/synthetic_corridor.h, ray
// cast here with the boxes in it), measured from the exact corners, outlined 4 px
// beyond their pixels as a person draws a rectangle. bench/standing_boxes.py gives the
// figures on the random POV-Ray scenes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>

#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>

#include "engine/scene/collision.h"
#include "metrology/measure.h"
#include "modeling/corridor_model.h"
#include "modeling/layout.h"
#include "modeling/shot_file.h"
#include "modeling/stand_up.h"
#include "tests/metrology/synthetic_corridor.h"

namespace pw::modeling {
namespace {
namespace fs = std::filesystem;
using metrology::testing::SyntheticCorridor;

struct Cabinet {
  glm::dvec3 lo, hi;  // model frame, lo.y = 0
};

// Where the ray first meets the box (slab method): the distance and the face's axis
// (0 x, 1 y, 2 z), or a negative distance.
std::pair<double, int> hitBox(const Cabinet& c, const glm::dvec3& o, const glm::dvec3& d) {
  double near = -1e300, far = 1e300;
  int axis = -1;
  for (int k = 0; k < 3; ++k) {
    if (std::abs(d[k]) < 1e-15) {
      if (o[k] < c.lo[k] || o[k] > c.hi[k]) return {-1, -1};
      continue;
    }
    double t0 = (c.lo[k] - o[k]) / d[k], t1 = (c.hi[k] - o[k]) / d[k];
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > near) near = t0, axis = k;
    far = std::min(far, t1);
  }
  return near <= far && near > 0 ? std::pair{near, axis} : std::pair{-1.0, -1};
}

// A corridor W x H x L metres seen straight down from 2 m before its near end, the eye
// `eyeM` above the floor, in a 640 x 480 photo at 600 px.
SyntheticCorridor straightCorridor(double widthM, double heightM, double lengthM, double eyeM) {
  SyntheticCorridor c;
  c.widthM = widthM, c.heightM = heightM, c.lengthM = lengthM;
  c.cameraZM = 2.0, c.cameraHeightM = eyeM;
  c.imageWidth = 640, c.imageHeight = 480, c.focalPx = 600;
  return c;
}

// The corridor's photo, one ray a pixel, each pixel `colourOf` the ray's direction and
// the corridor surface it meets.
cv::Mat rayCastPhoto(const SyntheticCorridor& c,
                     const std::function<cv::Vec3b(const glm::dvec3& d, const metrology::testing::Hit& wall)>& colourOf) {
  cv::Mat photo(c.imageHeight, c.imageWidth, CV_8UC3);
  for (int v = 0; v < c.imageHeight; ++v) {
    for (int u = 0; u < c.imageWidth; ++u) {
      const glm::dvec3 d = c.ray({u, v});
      photo.at<cv::Vec3b>(v, u) = colourOf(d, metrology::testing::castRay(c, c.eyeM(), d));
    }
  }
  return photo;
}

// A person's rectangle `marginPx` beyond the boxes' pixels as the measured camera sees them.
std::vector<glm::dvec2> rectangleAround(const metrology::Measurement& m, const std::vector<Cabinet>& boxes, double marginPx) {
  glm::dvec2 lo(1e300), hi(-1e300);
  for (const Cabinet& box : boxes) {
    for (int k = 0; k < 8; ++k) {
      const glm::dvec3 p(k & 1 ? box.hi.x : box.lo.x, k & 2 ? box.hi.y : box.lo.y, k & 4 ? box.hi.z : box.lo.z);
      const glm::dvec2 px(metrology::projectWithMeasurement(m, p));
      lo = glm::min(lo, px), hi = glm::max(hi, px);
    }
  }
  lo -= glm::dvec2(marginPx), hi += glm::dvec2(marginPx);
  return {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}};
}

struct Scene {
  SyntheticCorridor corridor;
  std::vector<Cabinet> cabinets;
  cv::Mat photo;
  metrology::Measurement measurement;
};

// The corridor (walls, floor and ceiling each a shade of their own, the floor tiled)
// with the cabinets in it, each face a shade of the cabinet's colour (lit from above and
// the left), 3 x 3 rays a pixel.
Scene makeScene() {
  Scene s;
  s.corridor.widthM = 2.6, s.corridor.heightM = 2.9, s.corridor.lengthM = 14;
  s.corridor.cameraXM = 0.2, s.corridor.cameraZM = 3.0, s.corridor.cameraHeightM = 1.55;
  s.corridor.yawDeg = 6, s.corridor.pitchDeg = -4, s.corridor.rollDeg = 1;
  s.corridor.imageWidth = 900, s.corridor.imageHeight = 640, s.corridor.focalPx = 720;
  const double w = s.corridor.widthM / 2;
  s.cabinets = {{{-w, 0, -3.2}, {-w + 0.5, 1.8, -2.2}},     // on the left wall, its side well seen
                {{w - 0.45, 0, -7.0}, {w, 1.2, -5.6}}};    // on the right wall, further
  const SyntheticCorridor& c = s.corridor;
  const cv::Vec3d faces[3] = {{60, 90, 200}, {90, 130, 235}, {40, 70, 160}};  // BGR: x, y (top), z faces
  s.photo.create(c.imageHeight, c.imageWidth, CV_8UC3);
  constexpr int kRays = 3;
  for (int v = 0; v < c.imageHeight; ++v) {
    for (int u = 0; u < c.imageWidth; ++u) {
      cv::Vec3d sum(0, 0, 0);
      for (int j = 0; j < kRays; ++j) {
        for (int i = 0; i < kRays; ++i) {
          const glm::dvec2 px(u - 0.5 + (i + 0.5) / kRays, v - 0.5 + (j + 0.5) / kRays);
          const glm::dvec3 d = c.ray(px);
          const metrology::testing::Hit wall = metrology::testing::castRay(c, c.eyeM(), d);
          double nearest = 1e300;
          cv::Vec3d colour(128, 128, 128);
          if (wall.plane >= 0) {
            const bool tile = wall.plane == static_cast<int>(metrology::Plane::kFloor) &&
                              (static_cast<int>(wall.s * 8) + static_cast<int>(wall.t * 40)) % 2;
            colour = cv::Vec3d(150 + 15 * wall.plane, 160 + 10 * wall.plane, 165 + 5 * wall.plane) * (tile ? 0.8 : 1.0);
          }
          for (const Cabinet& cab : s.cabinets) {
            const auto [t, axis] = hitBox(cab, c.eyeM(), d);
            if (t > 0 && t < nearest) nearest = t, colour = faces[axis];
          }
          sum += colour;
        }
      }
      s.photo.at<cv::Vec3b>(v, u) = cv::Vec3b(sum * (1.0 / (kRays * kRays)));
    }
  }
  auto measured = metrology::measureCorridor(c.shot());
  EXPECT_TRUE(measured.ok()) << measured.message();
  if (measured) s.measurement = *measured;
  return s;
}

const Scene& scene() {
  static const Scene s = makeScene();
  return s;
}

metrology::Cutout outlineOf(const Scene& s, const Cabinet& cab, metrology::CutoutShape shape) {
  glm::dvec2 lo(1e300), hi(-1e300);
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 p(i & 1 ? cab.hi.x : cab.lo.x, i & 2 ? cab.hi.y : 0.0, i & 4 ? cab.hi.z : cab.lo.z);
    const glm::dvec2 px = s.corridor.project(p);
    lo = glm::min(lo, px), hi = glm::max(hi, px);
  }
  lo -= 4.0, hi += 4.0;
  return {"cabinet", {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}}, shape};
}

TEST(StandingBoxes, ACabinetStandsAsABoxOfItsSize) {
  const Scene& s = scene();
  for (size_t k = 0; k < s.cabinets.size(); ++k) {
    SCOPED_TRACE("cabinet " + std::to_string(k));
    const Cabinet& cab = s.cabinets[k];
    auto stood = standUpObjects(s.photo, s.measurement, {outlineOf(s, cab, metrology::CutoutShape::kBox)});
    ASSERT_TRUE(stood.ok()) << stood.message();
    const StandingObject& box = stood->objects.at(0);
    const glm::dvec3 size = cab.hi - cab.lo;
    EXPECT_EQ(box.shape, metrology::CutoutShape::kBox);
    EXPECT_NEAR(box.heightM, size.y, 0.02 * size.y);
    EXPECT_NEAR(box.widthM, size.x, 0.08 * size.x);
    if (box.depthSeen) {
      EXPECT_NEAR(box.depthM, size.z, 2 * box.depthSigmaM);
      EXPECT_LT(box.depthSigmaM, 0.5 * box.depthM);
    } else {
      EXPECT_DOUBLE_EQ(box.depthM, 0.5);
    }
    EXPECT_NEAR(box.footM.x, 0.5 * (cab.lo.x + cab.hi.x), 0.08 * size.x);
    EXPECT_LE(std::abs(box.footM.x) + 0.5 * box.widthM, 0.5 * s.corridor.widthM + 1e-9) << "inside the walls";
    // Five faces on the floor and up to its top; those the camera sees carry the photo,
    // the others the cabinet's colour, all with its mask as alpha.
    ASSERT_EQ(box.faces.size(), 5u);
    int textured = 0;
    for (const StandingFace& face : box.faces) {
      for (const glm::dvec3& p : face.cornersM) EXPECT_TRUE(std::abs(p.y) < 1e-9 || std::abs(p.y - box.heightM) < 1e-9);
      const glm::dvec3 middle = 0.25 * (face.cornersM[0] + face.cornersM[1] + face.cornersM[2] + face.cornersM[3]);
      const bool seen = glm::dot(s.corridor.eyeM() - middle, face.normal) > 0;
      EXPECT_EQ(face.photo, seen);
      EXPECT_FALSE(face.image.rgba.empty()) << "the object's outline as alpha on every face";
      textured += seen;
      // Corners counter-clockwise seen from outside: their normal is the face's.
      const glm::dvec3 n = glm::cross(face.cornersM[1] - face.cornersM[0], face.cornersM[3] - face.cornersM[0]);
      EXPECT_GT(glm::dot(glm::normalize(n), face.normal), 0.999);
    }
    EXPECT_GE(textured, 2) << "its front and the side towards the camera (and its top when the camera is above it)";
  }
  // The first cabinet's side is seen well: its depth is measured, within its ±.
  auto first = standUpObjects(s.photo, s.measurement, {outlineOf(s, s.cabinets[0], metrology::CutoutShape::kBox)});
  ASSERT_TRUE(first.ok());
  EXPECT_TRUE(first->objects[0].depthSeen);
  EXPECT_NEAR(first->objects[0].depthM, 1.0, 0.1);
}

// The walk stops at the box, on its front and on its side, and the model says what it stood up.
TEST(StandingBoxes, TheWalkStopsAtTheBox) {
  const Scene& s = scene();
  auto model = makeCorridorModel("boxes", s.photo, s.measurement,
                                 {outlineOf(s, s.cabinets[0], metrology::CutoutShape::kBox)}, false, {});
  ASSERT_TRUE(model.ok()) << model.message();
  auto plan = planBuilding(chainLayout({"boxes.json"}), {model->box});
  ASSERT_TRUE(plan.ok()) << plan.message();
  const engine::Scene built = makeBuildingScene({*model}, *plan, {});
  bool said = false;
  for (const std::string& line : built.info) said = said || line.rfind("stood up: cabinet (boxes_standing_cabinet_*), a box", 0) == 0;
  EXPECT_TRUE(said);
  const StandingObject& box = model->standing.at(0);
  ASSERT_EQ(box.faces.size(), 5u);
  const engine::CollisionWorld world = engine::CollisionWorld::fromScene(built);
  constexpr float kRadius = 0.25f;
  const glm::dvec3 front = box.faces[0].cornersM[0], side = box.faces[3].cornersM[0];  // on the box's near corner
  // Towards the camera's end, 1 m before its front, walking 1.6 m along the corridor into it.
  const glm::vec3 ahead(0.5 * (box.faces[0].cornersM[0] + box.faces[0].cornersM[1]) + glm::dvec3(0, 1.0, 1.0));
  const glm::vec3 end = world.slideSphere(ahead, kRadius, glm::vec3(0, 0, -1.6f));
  EXPECT_GE(end.z - front.z, kRadius - 1e-3) << "the walker passed through its front";
  EXPECT_LT(end.z - front.z, kRadius + 0.05) << "the walker stopped short of it";
  // From the corridor's middle, walking across it into its side.
  const glm::vec3 across(side.x + 1.0, 1.0, 0.5 * (box.faces[3].cornersM[0].z + box.faces[3].cornersM[1].z));
  const glm::vec3 stop = world.slideSphere(across, kRadius, glm::vec3(-1.6f, 0, 0));
  EXPECT_GE(stop.x - side.x, kRadius - 1e-3) << "the walker passed through its side";
  EXPECT_LT(stop.x - side.x, kRadius + 0.05);
}

TEST(StandingBoxes, TheSameOutlineFlatIsOneCutOutAsBefore) {
  const Scene& s = scene();
  auto flat = standUpObjects(s.photo, s.measurement, {outlineOf(s, s.cabinets[0], metrology::CutoutShape::kFlat)});
  ASSERT_TRUE(flat.ok()) << flat.message();
  const StandingObject& cut = flat->objects.at(0);
  ASSERT_EQ(cut.faces.size(), 1u);
  EXPECT_EQ(cut.depthM, 0.0);
  EXPECT_FALSE(cut.faces[0].image.rgba.empty());
  EXPECT_NEAR(cut.faces[0].normal.y, 0.0, 1e-12);
}

TEST(StandingBoxes, ShotFilesKeepTheShapeAndABadOneSaysWhy) {
  const fs::path dir = fs::path(PW_BINARY_DIR) / "test-output" / "standing_box";
  fs::create_directories(dir);
  metrology::Shot shot = scene().corridor.shot();
  shot.imagePath = "synthetic.png";
  shot.cutouts = {outlineOf(scene(), scene().cabinets[0], metrology::CutoutShape::kBox),
                  outlineOf(scene(), scene().cabinets[1], metrology::CutoutShape::kFlat)};
  shot.cutouts[1].name = "other";
  ASSERT_TRUE(writeShotFile(dir / "boxes.json", shot).ok());
  const nlohmann::json doc = nlohmann::json::parse(std::ifstream(dir / "boxes.json"));
  EXPECT_EQ(doc["cutouts"][0]["shape"], "box");
  EXPECT_FALSE(doc["cutouts"][1].contains("shape")) << "flat, the default, is not written";
  auto again = readShotFile(dir / "boxes.json");
  ASSERT_TRUE(again.ok()) << again.message();
  EXPECT_EQ(again->cutouts, shot.cutouts);
  nlohmann::json bad = doc;
  bad["cutouts"][0]["shape"] = "cylinder";
  std::ofstream(dir / "bad.json") << bad.dump();
  auto read = readShotFile(dir / "bad.json");
  ASSERT_FALSE(read.ok());
  EXPECT_NE(read.message().find("cutouts[0]: its shape is \"flat\""), std::string::npos) << read.message();
}

}  // namespace
}  // namespace pw::modeling

namespace pw::modeling {
namespace {

// A box is not its object's exact shape: the object's pixels its outline leaves out
// stay painted where the photo shows them (not filled), so that from the photo's camera
// the model gives the photo back; those inside it are filled.
TEST(StandingBoxes, WhatTheBoxLeavesOutOfItsObjectStaysPainted) {
  const Scene& s = scene();
  // A post standing on the cabinet, in its colour: GrabCut keeps it with the cabinet,
  // the box does not reach up to it.
  cv::Mat photo = s.photo.clone();
  metrology::Cutout outline = outlineOf(s, s.cabinets[0], metrology::CutoutShape::kBox);
  const glm::dvec2 top = s.corridor.project({s.cabinets[0].lo.x + 0.25, s.cabinets[0].hi.y, s.cabinets[0].hi.z});
  const cv::Rect post(static_cast<int>(top.x) - 12, static_cast<int>(top.y) - 50, 24, 52);
  photo(post).setTo(cv::Scalar(60, 90, 200));
  for (int k : {0, 1}) outline.outlinePx[k].y = std::min(outline.outlinePx[k].y, post.y - 4.0);  // its top
  auto stood = standUpObjects(photo, s.measurement, {outline});
  ASSERT_TRUE(stood.ok()) << stood.message();
  std::vector<cv::Point2f> corners, hull;
  for (const StandingFace& face : stood->objects.at(0).faces) {
    for (const glm::dvec3& c : face.cornersM) {
      const glm::dvec2 px = s.corridor.project(c);
      corners.emplace_back(static_cast<float>(px.x), static_cast<float>(px.y));
    }
  }
  cv::convexHull(corners, hull);
  int outside = 0, kept = 0, inside = 0, filled = 0;
  for (int v = 0; v < photo.rows; ++v) {
    for (int u = 0; u < photo.cols; ++u) {
      const bool object = post.contains({u, v}) || hitBox(s.cabinets[0], s.corridor.eyeM(), s.corridor.ray({u, v})).first > 0;
      if (!object) continue;
      const double from = cv::pointPolygonTest(hull, cv::Point2f(static_cast<float>(u), static_cast<float>(v)), true);
      const bool same = stood->behind.at<cv::Vec3b>(v, u) == photo.at<cv::Vec3b>(v, u);
      if (from < -2) ++outside, kept += same;
      if (from > 2) ++inside, filled += !same;
    }
  }
  EXPECT_GT(outside, 200) << "the post stands above the box";
  EXPECT_EQ(kept, outside) << "the post stays painted behind";
  EXPECT_GT(filled, 0.9 * inside) << "the cabinet's pixels inside its box are filled";
}

// A hanging sign in a long, low corridor (the ceiling 0.5 m above the eye): near the
// camera its top row places it; 30 m down, where 4 px of that row move it metres, it is
// left painted, by name, rather than hung metres off.
TEST(HangingObjects, OneFarDownALowCorridorIsLeftPaintedByName) {
  const SyntheticCorridor c = straightCorridor(2.0, 2.2, 40, 1.7);
  const Cabinet nearSign{{-0.4, 1.7, -4.0}, {0.4, 2.2, -3.97}}, farSign{{-0.4, 1.7, -30.0}, {0.4, 2.2, -29.97}};
  const cv::Mat photo = rayCastPhoto(c, [&](const glm::dvec3& d, const metrology::testing::Hit& wall) {
    for (const Cabinet* sign : {&nearSign, &farSign}) {
      if (hitBox(*sign, c.eyeM(), d).first > 0) return cv::Vec3b(40, 60, 200);
    }
    return cv::Vec3b(static_cast<uint8_t>(150 + 15 * std::max(0, wall.plane)), 170, 180);
  });
  auto m = metrology::measureCorridor(c.shot());
  ASSERT_TRUE(m.ok()) << m.message();
  const auto outline = [&](const Cabinet& sign, const std::string& name) {
    return metrology::Cutout{name, rectangleAround(*m, {sign}, 4.0), metrology::CutoutShape::kHanging};
  };
  auto hung = standUpObjects(photo, *m, {outline(nearSign, "near sign")});
  ASSERT_TRUE(hung.ok()) << hung.message();
  // Measured: z -3.53 (true -3.985): the outline's top 4 px above the sign's, 0.12 m a pixel here.
  EXPECT_NEAR(hung->objects.at(0).footM.z, -3.985, 0.6);
  // The far one is left painted, by name: its pixels not filled (the photo's own behind it).
  auto refused = standUpObjects(photo, *m, {outline(farSign, "far sign")});
  ASSERT_TRUE(refused.ok()) << refused.message();
  EXPECT_TRUE(refused->objects.empty());
  ASSERT_EQ(refused->leftPainted.size(), 1u);
  EXPECT_NE(refused->leftPainted[0].find("cutout \"far sign\": where it hangs is not in the photo"), std::string::npos)
      << refused->leftPainted[0];
  const glm::dvec2 farPx(metrology::projectWithMeasurement(*m, 0.5 * (farSign.lo + farSign.hi)));
  const cv::Point far(static_cast<int>(std::lround(farPx.x)), static_cast<int>(std::lround(farPx.y)));
  EXPECT_EQ(refused->behind.at<cv::Vec3b>(far), cv::Vec3b(40, 60, 200));
  // With the near one: it still hangs.
  auto both = standUpObjects(photo, *m, {outline(nearSign, "near sign"), outline(farSign, "far sign")});
  ASSERT_TRUE(both.ok()) << both.message();
  ASSERT_EQ(both->objects.size(), 1u);
  EXPECT_EQ(both->objects[0].name, "near sign");
  EXPECT_EQ(both->leftPainted.size(), 1u);
  // The editor's preview, rebuilt as a corner moves: the fill about the near one alone is
  // made once and kept, as GrabCut's masks are.
  CutOutCache cache;
  for (int step = 0; step < 3; ++step) {
    auto rebuilt = standUpObjects(photo, *m, {outline(nearSign, "near sign"), outline(farSign, "far sign")}, &cache);
    ASSERT_TRUE(rebuilt.ok()) << rebuilt.message();
    EXPECT_EQ(rebuilt->leftPainted.size(), 1u);
    EXPECT_EQ(cv::norm(rebuilt->behind, both->behind, cv::NORM_INF), 0.0) << "step " << step;
  }
  EXPECT_EQ(cache.made(), 2) << "GrabCut and the fill about all once, the fill about the near sign once";
}

// A person whose legs are the floor's colour (TUNE seed 71's trouble): GrabCut keeps her
// torso only, its lowest pixel far above her feet; the outline, drawn down to where she
// stands, places her foot instead, within a pixel's worth of where she stands.
TEST(StandingObjects, AnObjectWhoseFootGrabCutLosesStandsWhereItsOutlineEnds) {
  const SyntheticCorridor c = straightCorridor(3.0, 2.8, 20, 1.6);
  const Cabinet torso{{-0.25, 0.9, -6.0}, {0.25, 1.7, -5.8}}, legs{{-0.15, 0.0, -6.0}, {0.15, 0.9, -5.8}};
  const cv::Vec3b floorColour(120, 130, 140);
  const cv::Mat photo = rayCastPhoto(c, [&](const glm::dvec3& d, const metrology::testing::Hit& wall) {
    if (hitBox(torso, c.eyeM(), d).first > 0) return cv::Vec3b(40, 60, 200);
    if (hitBox(legs, c.eyeM(), d).first > 0) return floorColour;  // legs the floor's colour
    return wall.plane == static_cast<int>(metrology::Plane::kFloor)
               ? floorColour
               : cv::Vec3b(static_cast<uint8_t>(170 + 15 * std::max(0, wall.plane)), 180, 190);
  });
  auto m = metrology::measureCorridor(c.shot());
  ASSERT_TRUE(m.ok()) << m.message();
  auto stood = standUpObjects(photo, *m, {metrology::Cutout{"her", rectangleAround(*m, {torso, legs}, 4.0)}});
  ASSERT_TRUE(stood.ok()) << stood.message();
  ASSERT_EQ(stood->objects.size(), 1u) << (stood->leftPainted.empty() ? "" : stood->leftPainted[0]);
  // The outline's bottom is 4 px below her feet' nearest edge (z -5.8): about 0.25 m nearer here.
  EXPECT_NEAR(stood->objects[0].footM.z, -5.8, 0.4);
}

}  // namespace
}  // namespace pw::modeling
