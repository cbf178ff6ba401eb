// Measuring objects (metrology/object_measure.h): a door on a side wall, a picture on
// the far wall, a person standing on the floor and a lamp hanging from the ceiling, in
// a synthetic corridor whose camera is written independently of the code under test
// (synthetic_corridor.h): exact pixels give the exact sizes; noisy pixels give sizes
// whose ± covers the truth as often as a standard deviation should.
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "metrology/object_measure.h"
#include "tests/metrology/synthetic_corridor.h"

namespace pw::metrology {
namespace {

using testing::SyntheticCorridor;

// The shot measured, then its points (measurePoints takes the measurement made).
Result<PointMeasurement> measureWithPoints(const Shot& shot, const MeasureOptions& options, const std::vector<ImagePoint>& points,
                                  const std::vector<ObjectMeasure>& asked) {
  auto m = measureCorridor(shot, options);
  if (!m) return m.error();
  return measurePoints(shot, options, *m, points, asked);
}

// A corridor seen turned and tilted, with the objects' true points (model frame).
struct Scene {
  SyntheticCorridor corridor;
  // A door 0.9 x 2.05 m on the left wall, 3-3.9 m before the far wall.
  glm::dvec3 doorBottomNear{-1.2, 0, -6.5}, doorBottomFar{-1.2, 0, -6.5 - 0.9}, doorTopNear{-1.2, 2.05, -6.5};
  // A picture 0.8 x 0.6 m on the far wall.
  glm::dvec3 pictureTopLeft{-0.6, 1.9, -9.5}, pictureTopRight{0.2, 1.9, -9.5}, pictureBottomLeft{-0.6, 1.3, -9.5};
  // A person 1.78 m tall standing 5 m in; a lamp hanging 0.55 m from the ceiling.
  glm::dvec3 feet{0.35, 0, -5.0}, head{0.35, 1.78, -5.0};
  glm::dvec3 lampTop{-0.2, 2.8, -3.0}, lampBottom{-0.2, 2.25, -3.0};

  Scene() {
    corridor.widthM = 2.4, corridor.heightM = 2.8, corridor.lengthM = 9.5;
    corridor.cameraXM = 0.3, corridor.cameraHeightM = 1.55, corridor.cameraZM = 4.5;
    corridor.yawDeg = 6, corridor.pitchDeg = -4, corridor.rollDeg = 2;
  }
  std::vector<ImagePoint> points() const {
    const auto at = [&](const glm::dvec3& p) { return corridor.project(p); };
    return {{"door_bottom_near", at(doorBottomNear), {PointSurface::kFloor}},
            {"door_bottom_far", at(doorBottomFar), {PointSurface::kLeftWall}},
            {"door_top_near", at(doorTopNear), {PointSurface::kLeftWall}},
            {"picture_top_left", at(pictureTopLeft), {PointSurface::kFarWall}},
            {"picture_top_right", at(pictureTopRight), {PointSurface::kFarWall}},
            {"picture_bottom_left", at(pictureBottomLeft), {PointSurface::kFarWall}},
            {"feet", at(feet), {PointSurface::kFloor}},
            {"head", at(head), {PointSurface::kAbove, "feet"}},
            {"lamp_top", at(lampTop), {PointSurface::kCeiling}},
            {"lamp_bottom", at(lampBottom), {PointSurface::kAbove, "lamp_top"}}};
  }
  static std::vector<ObjectMeasure> asked() {
    return {{ObjectQuantity::kDistance, "door_bottom_near", "door_bottom_far"},
            {ObjectQuantity::kHeight, "door_bottom_near", "door_top_near"},
            {ObjectQuantity::kDistance, "picture_top_left", "picture_top_right"},
            {ObjectQuantity::kDistance, "picture_top_left", "picture_bottom_left"},
            {ObjectQuantity::kHeight, "feet", "head"},
            {ObjectQuantity::kHeight, "lamp_bottom", "lamp_top"}};
  }
  static constexpr double kTruth[] = {0.9, 2.05, 0.8, 0.6, 1.78, 0.55};
};

TEST(ObjectMeasure, ExactPointsGiveTheExactSizes) {
  const Scene scene;
  auto measured = measureWithPoints(scene.corridor.shot(), {}, scene.points(), Scene::asked());
  ASSERT_TRUE(measured.ok()) << measured.message();
  ASSERT_EQ(measured->results.size(), 6u);
  for (size_t i = 0; i < 6; ++i) {
    const ObjectResult& r = measured->results[i];
    EXPECT_NEAR(r.valueM, Scene::kTruth[i], 1e-6 * Scene::kTruth[i]) << r.asked.from << "-" << r.asked.to;
    EXPECT_GT(r.sigmaM, 0.0);
    EXPECT_LT(r.sigmaM, 0.3 * Scene::kTruth[i]);  // the door's width along a wall seen at a grazing angle: 0.20 m
  }
  // Each point where it is, and how far from the camera and the far wall.
  const LocatedPoint& feet = measured->points[6];
  EXPECT_NEAR(glm::length(feet.m - scene.feet), 0.0, 1e-6);
  EXPECT_NEAR(feet.fromFarWallM, 4.5, 1e-6);
  EXPECT_NEAR(feet.fromCameraM, std::hypot(0.35 - 0.3, -5.0 - 4.5), 1e-6);
}

TEST(ObjectMeasure, TheSeedsConstructionGivesTheSameSizesWhereItIsExact) {
  // The seed paper's one-point perspective: the camera straight down the corridor.
  Scene scene;
  scene.corridor.yawDeg = scene.corridor.pitchDeg = scene.corridor.rollDeg = 0;
  MeasureOptions seed;
  seed.method = Method::kSeed;
  auto measured = measureWithPoints(scene.corridor.shot(), seed, scene.points(), Scene::asked());
  ASSERT_TRUE(measured.ok()) << measured.message();
  for (size_t i = 0; i < 6; ++i) EXPECT_NEAR(measured->results[i].valueM, Scene::kTruth[i], 1e-6 * Scene::kTruth[i]);
}

TEST(ObjectMeasure, TheSigmaCoversTheTruthAsOftenAsItShould) {
  // 1 px of noise on every corner and every point: the truth within 2 sigma in about
  // 95% of the trials (95 +- 3 asked), per quantity and over all.
  const Scene scene;
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 1.0);
  constexpr int kTrials = 200;
  int covered = 0, total = 0;
  std::vector<int> perQuantity(6, 0);
  for (int trial = 0; trial < kTrials; ++trial) {
    Shot shot = scene.corridor.shot();
    for (glm::dvec2& c : shot.cornersPx) c += glm::dvec2(noise(rng), noise(rng));
    std::vector<ImagePoint> points = scene.points();
    for (ImagePoint& p : points) p.px += glm::dvec2(noise(rng), noise(rng));
    auto measured = measureWithPoints(shot, {}, points, Scene::asked());
    ASSERT_TRUE(measured.ok()) << measured.message();
    for (size_t i = 0; i < 6; ++i) {
      const ObjectResult& r = measured->results[i];
      const bool in = std::abs(r.valueM - Scene::kTruth[i]) <= 2 * r.sigmaM;
      covered += in, perQuantity[i] += in, ++total;
    }
  }
  const double share = 100.0 * covered / total;
  std::printf("2-sigma coverage over %d values: %.1f%% (", total, share);
  for (size_t i = 0; i < 6; ++i) std::printf("%s%.1f", i ? ", " : "", 100.0 * perQuantity[i] / kTrials);
  std::printf(")\n");
  EXPECT_GE(share, 92.0);
  EXPECT_LE(share, 98.0);
  for (size_t i = 0; i < 6; ++i) EXPECT_GE(100.0 * perQuantity[i] / kTrials, 88.0) << i;
}

TEST(ObjectMeasure, ErrorsNameThePoint) {
  const Scene scene;
  auto m = measureCorridor(scene.corridor.shot());
  ASSERT_TRUE(m.ok());
  // Above the horizon, a floor point is behind the camera.
  auto sky = locatePoints(*m, {{"sky", {400, 5}, {PointSurface::kFloor}}});
  ASSERT_FALSE(sky.ok());
  EXPECT_NE(sky.message().find("point \"sky\""), std::string::npos) << sky.message();
  EXPECT_NE(sky.message().find("does not meet the floor"), std::string::npos) << sky.message();
  auto orphan = locatePoints(*m, {{"head", {400, 300}, {PointSurface::kAbove, "feet"}}});
  ASSERT_FALSE(orphan.ok());
  EXPECT_NE(orphan.message().find("\"feet\", which is not a point given before it"), std::string::npos);
  auto twice = locatePoints(*m, {{"a", {400, 500}, {PointSurface::kFloor}}, {"a", {410, 500}, {PointSurface::kFloor}}});
  ASSERT_FALSE(twice.ok());
  auto unknown = measureWithPoints(scene.corridor.shot(), {}, scene.points(), {{ObjectQuantity::kDistance, "feet", "nowhere"}});
  ASSERT_FALSE(unknown.ok());
  EXPECT_NE(unknown.message().find("\"nowhere\": no such point"), std::string::npos) << unknown.message();
  std::string above;
  EXPECT_EQ(surfaceFromName("above:feet", &above), PointSurface::kAbove);
  EXPECT_EQ(above, "feet");
  EXPECT_EQ(surfaceFromName("wall:far", nullptr), PointSurface::kFarWall);
  EXPECT_FALSE(surfaceFromName("wall", nullptr).has_value());
}

}  // namespace
}  // namespace pw::metrology
