// Buildings of several corridors from the ground-truth shots (tests/groundtruth): the openings between them
// exist (a ray from one corridor into the next is not blocked) and views render.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>

#include "modeling/pipeline.h"
#include "engine/gpu/renderer.h"
#include "engine/scene/collision.h"
#include "tests/support/groundtruth.h"

namespace pw::modeling {
namespace {
namespace fs = std::filesystem;

fs::path shot(const char* name) { return groundtruth::groundTruthShot(name); }

glm::vec3 apply(const glm::dmat4& m, const glm::dvec3& p) { return glm::vec3(m * glm::dvec4(p, 1.0)); }

TEST(Building, TwoCorridorsEndToEndOpenIntoEachOther) {
  auto built = modeling::buildModel(modeling::chainLayout({shot("corridor_a"), shot("corridor_c")}), {});
  ASSERT_TRUE(built.ok()) << built.message();
  const auto world = engine::CollisionWorld::fromScene(built->scene);
  const auto& plan = built->plan;
  const double lengthA = built->corridors[0].box.lengthM, lengthC = built->corridors[1].box.lengthM;
  // From the middle of a, at knee height, straight on: the ray passes a's far wall
  // (opened) and stops at c's far wall.
  const glm::vec3 from = apply(plan.worldFromCorridor[0], {0, 0.5, -lengthA / 2});
  auto hit = world.raycast(from, {0, 0, -1}, 100);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->distance, lengthA / 2 + lengthC, 1e-3);
  // Above the opening (a is 2.8 m high, c 2.5 m) a's far wall is still there.
  auto lintel = world.raycast(apply(plan.worldFromCorridor[0], {0, 2.65, -lengthA / 2}), {0, 0, -1}, 100);
  ASSERT_TRUE(lintel);
  EXPECT_NEAR(lintel->distance, lengthA / 2, 1e-3);
}

TEST(Building, ThreeCorridorsWithASideWingRenderAndOpen) {
  modeling::Layout layout = modeling::chainLayout({shot("corridor_b"), shot("corridor_c"), shot("corridor_a")});
  layout.corridors[1].attach = modeling::Attachment{0, modeling::Side::kLeft, 6.0};   // a wing off b's left wall
  layout.corridors[2].attach = modeling::Attachment{0, modeling::Side::kFar, 0.0};    // a continues b
  auto built = modeling::buildModel(layout, {});
  ASSERT_TRUE(built.ok()) << built.message();
  const auto world = engine::CollisionWorld::fromScene(built->scene);
  const auto& plan = built->plan;
  const double widthB = built->corridors[0].box.widthM, lengthWing = built->corridors[1].box.lengthM;
  // From b's centre line at the wing's offset, looking left (-x in b): through b's
  // left wall into the wing, to the wing's far wall.
  const glm::vec3 from = apply(plan.worldFromCorridor[0], {0, 1.0, -6.0});
  const glm::vec3 left = glm::vec3(glm::dmat3(plan.worldFromCorridor[0]) * glm::dvec3(-1, 0, 0));
  auto hit = world.raycast(from, left, 100);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->distance, widthB / 2 + lengthWing, 1e-3);
  // Two metres further along b, the left wall is closed.
  auto wall = world.raycast(apply(plan.worldFromCorridor[0], {0, 1.0, -8.5}), left, 100);
  ASSERT_TRUE(wall);
  EXPECT_NEAR(wall->distance, widthB / 2, 1e-3);

  // Every viewpoint renders and shows the building: the share of the frame that is not
  // background, measured 2026-11-29, within 2 points (a view inside a corridor fills
  // the frame, looking back it ends in the open near end; the overview, a cutaway from
  // high above b's centre line, sees b's floor, both its walls and its far wall, the
  // wing's floor and the walls facing it: a long, narrow building in a wide frame).
  const std::map<std::string, double> kMeasuredCover = {
      {"Photo", 1.0},    {"Entrance", 1.0},           {"Far end looking back", 0.9854},
      {"Overview", 0.0454}, {"corridor_c: entrance", 1.0}, {"corridor_a: entrance", 1.0}};
  engine::RendererOptions options;
  options.forceCpu = true;
  options.validation = engine::RendererOptions::Validation::kOn;
  auto renderer = engine::Renderer::create(options);
  ASSERT_TRUE(renderer.ok()) << renderer.message();
  ASSERT_TRUE((*renderer)->setScene(built->scene).ok());
  ASSERT_EQ(built->scene.viewpoints.size(), 6u);
  for (const auto& vp : built->scene.viewpoints) {
    auto image = (*renderer)->renderToImage(engine::cameraFromViewpoint(vp), 320, 180);
    ASSERT_TRUE(image.ok()) << vp.description << ": " << image.message();
    size_t lit = 0;
    for (size_t i = 0; i < image->rgba.size(); i += 4) lit += (image->rgba[i] | image->rgba[i + 1] | image->rgba[i + 2]) != 0;
    const double cover = double(lit) / (image->rgba.size() / 4);
    ASSERT_TRUE(kMeasuredCover.count(vp.description)) << "a viewpoint this test does not know: " << vp.description;
    EXPECT_NEAR(cover, kMeasuredCover.at(vp.description), 0.02) << vp.description;
  }
  EXPECT_EQ((*renderer)->validationMessageCount(), 0u);
}

}  // namespace
}  // namespace pw::modeling
