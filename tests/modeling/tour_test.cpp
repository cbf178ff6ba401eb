#include "modeling/tour.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

namespace pw::modeling {
namespace {

// Is p inside corridor c of the plan (with a margin from its walls)?
bool insideSomeCorridor(const BuildingPlan& plan, const std::vector<metrology::Dimensions>& boxes, const glm::dvec3& p,
                        double startZ) {
  for (size_t c = 0; c < boxes.size(); ++c) {
    const glm::dvec3 local = glm::dvec3(glm::inverse(plan.worldFromCorridor[c]) * glm::dvec4(p, 1.0));
    const double nearZ = c == 0 ? startZ : 0.0;
    if (std::abs(local.x) <= boxes[c].widthM / 2 + 1e-6 && local.z <= nearZ + 1e-6 &&
        local.z >= -boxes[c].lengthM - 1e-6) {
      return true;
    }
  }
  return false;
}

TEST(Tour, SingleCorridorWalksToTheEndAndBack) {
  const Layout layout = chainLayout({"a.json"});
  const std::vector<metrology::Dimensions> boxes{{2, 3, 10}};
  auto plan = planBuilding(layout, boxes);
  ASSERT_TRUE(plan.ok());
  TourOptions options;
  options.startZ = 2.0;
  const auto waypoints = tourWaypoints(layout, boxes, *plan, options);
  ASSERT_EQ(waypoints.size(), 3u);
  EXPECT_NEAR(waypoints[1].z, -9.0, 1e-9);  // one metre before the far wall
  const TourPath path(waypoints, options);
  // 11 m there, 11 m back at 1.2 m/s, plus two half turns at 90 deg/s.
  EXPECT_NEAR(path.durationS(), 22.0 / 1.2 + 4.0, 1e-6);
  glm::dvec3 p;
  double yaw = 0;
  path.sample(0, p, yaw);
  EXPECT_NEAR(p.z, 2.0, 1e-9);
  EXPECT_NEAR(yaw, 0.0, 1e-9);
  path.sample(path.durationS(), p, yaw);
  EXPECT_NEAR(p.z, 2.0, 1e-9);
}

TEST(Tour, BuildingTourStaysInsideAndMovesSmoothly) {
  Layout layout = chainLayout({"a.json", "b.json", "c.json"});
  layout.corridors[1].attach = Attachment{0, Side::kLeft, 5.0};
  layout.corridors[2].attach = Attachment{0, Side::kFar, 0.0};
  const std::vector<metrology::Dimensions> boxes{{2.4, 2.8, 10}, {2, 2.6, 6}, {3, 3, 8}};
  auto plan = planBuilding(layout, boxes);
  ASSERT_TRUE(plan.ok()) << plan.message();
  TourOptions options;
  const TourPath path(tourWaypoints(layout, boxes, *plan, options), options);
  const auto cameras = path.cameras(600, 1.0f);
  ASSERT_EQ(cameras.size(), 600u);
  const double stepS = path.durationS() / 599;
  double farthestX = 0, farthestZ = 0;
  for (size_t i = 0; i < cameras.size(); ++i) {
    const glm::dvec3 p(cameras[i].position);
    EXPECT_TRUE(insideSomeCorridor(*plan, boxes, p, 0.0)) << "frame " << i << " at " << p.x << " " << p.z;
    EXPECT_NEAR(p.y, 1.6, 1e-6);
    if (i > 0) {
      EXPECT_LE(glm::distance(p, glm::dvec3(cameras[i - 1].position)), options.walkSpeedMps * stepS * 1.6 + 1e-6);
      const float turn = glm::angle(cameras[i].orientation * glm::inverse(cameras[i - 1].orientation));
      EXPECT_LE(turn, glm::radians(options.turnSpeedDegPerS) * stepS * 1.6 + 0.02) << "frame " << i;
    }
    farthestX = std::min(farthestX, p.x);
    farthestZ = std::min(farthestZ, p.z);
  }
  EXPECT_LT(farthestX, -1.2 - 6 + 1.5);     // went down the left wing
  EXPECT_LT(farthestZ, -10.0 - 8 + 1.5);    // and through to the far corridor's end
}

}  // namespace
}  // namespace pw::modeling
