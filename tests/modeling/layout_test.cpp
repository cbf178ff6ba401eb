#include "modeling/layout.h"

#include <gtest/gtest.h>

#include <fstream>

namespace pw::modeling {
namespace {
namespace fs = std::filesystem;

fs::path writeTemp(const std::string& name, const std::string& text) {
  const fs::path path = fs::temp_directory_path() / ("pw_layout_" + name);
  std::ofstream(path) << text;
  return path;
}

glm::dvec3 apply(const glm::dmat4& m, const glm::dvec3& p) { return glm::dvec3(m * glm::dvec4(p, 1.0)); }

TEST(Layout, ReadsPlacedAndAttachedCorridors) {
  const fs::path path = writeTemp("ok.json", R"({"corridors": [
    {"name": "hall", "shot": "a.json", "position": [1, 0, 2], "rotation_deg": 90},
    {"name": "wing", "shot": "sub/b.json", "attach": {"to": "hall", "side": "left", "offset_m": 3}}]})");
  auto layout = readLayoutFile(path);
  ASSERT_TRUE(layout.ok()) << layout.message();
  ASSERT_EQ(layout->corridors.size(), 2u);
  EXPECT_EQ(layout->corridors[0].position, glm::dvec3(1, 0, 2));
  EXPECT_EQ(layout->corridors[1].shot, path.parent_path() / "sub/b.json");
  ASSERT_TRUE(layout->corridors[1].attach);
  EXPECT_EQ(layout->corridors[1].attach->to, 0);
  EXPECT_EQ(layout->corridors[1].attach->side, Side::kLeft);
}

TEST(Layout, AttachingToAnUnknownCorridorIsAnError) {
  auto layout = readLayoutFile(writeTemp("bad.json", R"({"corridors": [
    {"name": "wing", "shot": "b.json", "attach": {"to": "hall"}}]})"));
  ASSERT_FALSE(layout.ok());
  EXPECT_NE(layout.message().find("\"hall\""), std::string::npos);
}

TEST(Layout, BadSideIsAnError) {
  auto layout = readLayoutFile(writeTemp("side.json", R"({"corridors": [{"name": "a", "shot": "a.json"},
    {"name": "b", "shot": "b.json", "attach": {"to": "a", "side": "up"}}]})"));
  ASSERT_FALSE(layout.ok());
  EXPECT_NE(layout.message().find("side"), std::string::npos);
}

TEST(Layout, FarAttachmentContinuesTheCorridor) {
  const Layout layout = chainLayout({"a.json", "b.json"});
  auto plan = planBuilding(layout, {{2, 3, 10}, {3, 2.5, 5}});
  ASSERT_TRUE(plan.ok()) << plan.message();
  // b's near-end centre sits on a's far wall.
  const glm::dvec3 p = apply(plan->worldFromCorridor[1], {0, 0, 0});
  EXPECT_NEAR(p.z, -10.0, 1e-9);
  EXPECT_NEAR(p.x, 0.0, 1e-9);
  // The opening in a's far wall is a's full width (b is wider) and b's height.
  ASSERT_EQ(plan->openings.size(), 2u);
  EXPECT_EQ(plan->openings[0].surface, Surface::kFarWall);
  EXPECT_NEAR(plan->openings[0].rect.s0, 0.0, 1e-9);
  EXPECT_NEAR(plan->openings[0].rect.s1, 2.0, 1e-9);
  EXPECT_NEAR(plan->openings[0].rect.t1, 2.5, 1e-9);
  // In b's near end (3 m wide) the overlap is the middle 2 m.
  EXPECT_EQ(plan->openings[1].surface, Surface::kNearEnd);
  EXPECT_NEAR(plan->openings[1].rect.s0, 0.5, 1e-9);
  EXPECT_NEAR(plan->openings[1].rect.s1, 2.5, 1e-9);
}

// Issue 23's finding: corridors that run through each other were accepted without a
// word. Attached corridors touch at their opening and do not overlap; two placed ones
// crossing do, with the floor they share.
TEST(Layout, CorridorsThatRunThroughEachOtherAreFoundAttachedOnesAreNot) {
  Layout chained = chainLayout({"a.json", "b.json"});
  chained.corridors[1].attach = Attachment{0, Side::kLeft, 4.0};
  auto attached = planBuilding(chained, {{2, 3, 10}, {1.5, 3, 6}});
  ASSERT_TRUE(attached.ok()) << attached.message();
  EXPECT_TRUE(attached->overlaps.empty());

  Layout crossing = chainLayout({"a.json", "b.json"});
  crossing.corridors[0].name = "hall";
  crossing.corridors[1].name = "wing";
  crossing.corridors[1].attach.reset();
  crossing.corridors[1].position = {0, 0, -3};  // 2 m wide, 10 m long: crosses the hall
  crossing.corridors[1].rotationDeg = 90;
  auto plan = planBuilding(crossing, {{2, 3, 10}, {2, 3, 10}});
  ASSERT_TRUE(plan.ok()) << plan.message();
  ASSERT_EQ(plan->overlaps.size(), 1u);
  EXPECT_EQ(plan->overlaps[0].a, 0);
  EXPECT_EQ(plan->overlaps[0].b, 1);
  EXPECT_NEAR(plan->overlaps[0].areaM2, 2.0, 1e-3);  // from the hall's centre line to its wall (1 m), 2 m wide
  const std::string text = overlapText(crossing, plan->overlaps[0]);
  EXPECT_NE(text.find("\"hall\" and \"wing\" run through each other"), std::string::npos) << text;
}

TEST(Layout, LeftAttachmentTurnsAndOpensTheWall) {
  Layout layout = chainLayout({"a.json", "b.json"});
  layout.corridors[1].attach = Attachment{0, Side::kLeft, 4.0};
  auto plan = planBuilding(layout, {{2, 3, 10}, {1.5, 3, 6}});
  ASSERT_TRUE(plan.ok()) << plan.message();
  const glm::dvec3 nearCentre = apply(plan->worldFromCorridor[1], {0, 0, 0});
  const glm::dvec3 farCentre = apply(plan->worldFromCorridor[1], {0, 0, -6});
  EXPECT_NEAR(nearCentre.x, -1.0, 1e-9);
  EXPECT_NEAR(nearCentre.z, -4.0, 1e-9);
  EXPECT_NEAR(farCentre.x, -7.0, 1e-9);  // runs off to the left (-x)
  EXPECT_NEAR(farCentre.z, -4.0, 1e-9);
  EXPECT_EQ(plan->openings[0].surface, Surface::kLeftWall);
  EXPECT_NEAR(plan->openings[0].rect.s0, 3.25, 1e-9);
  EXPECT_NEAR(plan->openings[0].rect.s1, 4.75, 1e-9);
}

TEST(Layout, OpeningPastTheWallsEndIsAnError) {
  Layout layout = chainLayout({"a.json", "b.json"});
  layout.corridors[1].attach = Attachment{0, Side::kRight, 9.5};
  auto plan = planBuilding(layout, {{2, 3, 10}, {1.5, 3, 6}});
  ASSERT_FALSE(plan.ok());
  EXPECT_NE(plan.message().find("does not fit"), std::string::npos);
}

}  // namespace
}  // namespace pw::modeling
