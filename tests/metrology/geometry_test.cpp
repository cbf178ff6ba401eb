// Vanishing points, the camera convention shared with the engine, and the seed
// construction's intermediate points.
#include <cmath>

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

#include "engine/scene/camera.h"
#include "metrology/corridor_frame.h"
#include "metrology/measure.h"
#include "metrology/seed_method.h"
#include "metrology/vanishing.h"
#include "tests/metrology/synthetic_corridor.h"

namespace pw::metrology {
namespace {

using testing::SyntheticCorridor;

TEST(Vanishing, LinesThroughAPointMeetThere) {
  const glm::dvec2 vp(321.5, 205.25);
  const Segment s[] = {{vp + glm::dvec2(-300, 250), vp + glm::dvec2(-30, 25)},
                       {vp + glm::dvec2(280, 260), vp + glm::dvec2(14, 13)},
                       {vp + glm::dvec2(-250, -300), vp + glm::dvec2(-50, -60)}};
  auto v = fitVanishingPoint(s);
  ASSERT_TRUE(v.ok());
  EXPECT_TRUE(v->finite);
  EXPECT_NEAR(v->px.x, vp.x, 1e-8);
  EXPECT_NEAR(v->px.y, vp.y, 1e-8);
  EXPECT_NEAR(v->residualPx, 0, 1e-8);
}

TEST(Vanishing, LeastSquaresPointAndResidualForInconsistentLines) {
  // Three lines forming a small triangle: the point lies inside it, residual > 0.
  const Segment s[] = {{{0, 0}, {100, 0}}, {{0, 10}, {100, 110}}, {{100, 10}, {0, 110}}};
  auto v = fitVanishingPoint(s);
  ASSERT_TRUE(v.ok());
  ASSERT_TRUE(v->finite);
  EXPECT_GT(v->px.y, 0);
  EXPECT_LT(v->px.y, 60);
  EXPECT_NEAR(v->px.x, 50, 1e-6);
  EXPECT_GT(v->residualPx, 0.1);
}

TEST(Vanishing, ParallelLinesMeetAtInfinityInTheirDirection) {
  const Segment s[] = {{{0, 0}, {100, 50}}, {{0, 100}, {100, 150}}, {{10, 300}, {210, 400}}};
  auto v = fitVanishingPoint(s);
  ASSERT_TRUE(v.ok());
  EXPECT_FALSE(v->finite);
  EXPECT_NEAR(v->direction.x, 2 / std::sqrt(5.0), 1e-9);
  EXPECT_NEAR(v->direction.y, 1 / std::sqrt(5.0), 1e-9);
  EXPECT_NEAR(v->homogeneous.z, 0, 1e-12);
}

TEST(Vanishing, TooFewOrEmptyLinesAreErrors) {
  const Segment one[] = {{{0, 0}, {1, 1}}};
  EXPECT_FALSE(fitVanishingPoint(one).ok());
  const Segment empty[] = {{{5, 5}, {5, 5}}, {{0, 0}, {1, 1}}};
  EXPECT_FALSE(fitVanishingPoint(empty).ok());
}

TEST(CorridorFrame, AnglesRoundTrip) {
  for (double yaw : {-10.0, 0.0, 7.5}) {
    for (double pitch : {-9.0, 0.0, 10.0}) {
      for (double roll : {-10.0, 3.0}) {
        const glm::dvec3 ypr = yawPitchRollFromRotation(
            rotationFromYawPitchRoll(glm::radians(yaw), glm::radians(pitch), glm::radians(roll)));
        EXPECT_NEAR(glm::degrees(ypr.x), yaw, 1e-9);
        EXPECT_NEAR(glm::degrees(ypr.y), pitch, 1e-9);
        EXPECT_NEAR(glm::degrees(ypr.z), roll, 1e-9);
      }
    }
  }
}

// A renderer placed at the measured camera with the shot's intrinsics draws the
// box's corners where the photo has them: checked with the engine's own camera
// maths (quaternion orientation, view matrix, projectToPixel).
TEST(CorridorFrame, EngineCameraAtTheMeasuredPoseReproducesThePhoto) {
  SyntheticCorridor c;
  c.cameraXM = -0.4;
  c.yawDeg = -7;
  c.pitchDeg = 6;
  c.rollDeg = 4;
  auto m = measureCorridor(c.shot());
  ASSERT_TRUE(m.ok()) << m.message();
  engine::Camera camera;
  camera.position = glm::vec3(m->pose.positionM);
  camera.orientation = glm::quat_cast(glm::mat3(m->pose.worldFromCamera));
  camera.intrinsics = engine::Intrinsics{m->camera.focalPx, m->camera.focalPx, m->camera.principalPointPx.x,
                                         m->camera.principalPointPx.y};
  const auto clicked = c.cornersPx();
  for (int i = 0; i < kCornerCount; ++i) {
    const glm::dvec3 p = engine::projectToPixel(camera, c.imageWidth, c.imageHeight, glm::vec3(m->cornersM[i]));
    EXPECT_GT(p.z, 0);
    EXPECT_NEAR(p.x, clicked[i].x, 2e-3) << cornerName(i);
    EXPECT_NEAR(p.y, clicked[i].y, 2e-3) << cornerName(i);
  }
  // The same orientation built independently from glm's quaternions about Y, X, Z.
  const glm::dquat q = glm::angleAxis(glm::radians(c.yawDeg), glm::dvec3(0, 1, 0)) *
                       glm::angleAxis(glm::radians(c.pitchDeg), glm::dvec3(1, 0, 0)) *
                       glm::angleAxis(glm::radians(c.rollDeg), glm::dvec3(0, 0, 1));
  const glm::dmat3 r = glm::mat3_cast(q);
  for (int col = 0; col < 3; ++col) {
    for (int row = 0; row < 3; ++row) EXPECT_NEAR(m->pose.worldFromCamera[col][row], r[col][row], 1e-7);
  }
}

TEST(SeedMethod, ConstructionPointsFollowThePaper) {
  SyntheticCorridor c;  // one-point perspective, VP at the principal point
  c.cameraXM = 0.3;
  auto s = seedConstruct(c.cornersPx(), c.focalPx, c.cameraHeightM);
  ASSERT_TRUE(s.ok()) << s.message();
  const double sc = s->drawingScalePxPerM;
  // Ground line s·h below VP, picture plane f above it.
  EXPECT_NEAR(s->groundLineV - s->vanishingPointPx.y, sc * c.cameraHeightM, 1e-9);
  EXPECT_NEAR(s->vanishingPointPx.y - s->picturePlaneV, c.focalPx, 1e-9);
  // Pg = (cx + s X, cy + s h) and Pa = (cx + s X, cy - s Z) for P5 (left, near).
  const SeedFloorPoint& p5 = s->floor[P5 - P3];
  const double x5 = -c.widthM / 2 - c.cameraXM, z5 = c.cameraZM;
  EXPECT_NEAR(p5.groundPoint.x, s->vanishingPointPx.x + sc * x5, 1e-6);
  EXPECT_NEAR(p5.groundPoint.y, s->groundLineV, 1e-9);
  ASSERT_TRUE(p5.planPoint.has_value());
  EXPECT_NEAR(p5.planPoint->y, s->vanishingPointPx.y - sc * z5, 1e-6);
  ASSERT_TRUE(p5.depthM.has_value());
  EXPECT_NEAR(*p5.depthM, z5, 1e-9);
  // Height point Pgp for P7 over P5 lies s·H above Pg.
  EXPECT_NEAR(p5.groundPoint.y - s->heightPoint[2].y, sc * c.heightM, 1e-6);
  EXPECT_NEAR(s->widthM, c.widthM, 1e-9);
  EXPECT_NEAR(s->heightM, c.heightM, 1e-9);
  EXPECT_NEAR(s->lengthM, c.lengthM, 1e-9);
  EXPECT_NEAR(s->cameraXM, c.cameraXM, 1e-9);
}

TEST(SeedMethod, CameraAboveAWallFootIsRefusedNotNaN) {
  // The left wall seen edge-on: P3 and P5 lie straight below VP and P1, P7 straight
  // above it, so the paper's height and depth lines are parallel and never meet.
  SyntheticCorridor c;
  c.cameraXM = -c.widthM / 2;
  auto s = seedConstruct(c.cornersPx(), c.focalPx, c.cameraHeightM);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("cannot be constructed"), std::string::npos) << s.message();
  auto m = measureCorridor(c.shot());
  ASSERT_FALSE(m.ok());
  EXPECT_NE(m.message().find("left wall plane is degenerate"), std::string::npos) << m.message();
}

}  // namespace
}  // namespace pw::metrology
