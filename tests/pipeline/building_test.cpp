// Buildings of several corridors from the shared shots: the openings between them
// exist (a ray from one corridor into the next is not blocked) and views render.
#include <gtest/gtest.h>

#include <filesystem>

#include "editor/pipeline.h"
#include "engine/gpu/renderer.h"
#include "engine/scene/collision.h"

namespace pw::editor {
namespace {
namespace fs = std::filesystem;

fs::path shot(const char* name) { return fs::path(PW_SHARED_DIR) / "corridors" / (std::string(name) + ".json"); }

glm::vec3 apply(const glm::dmat4& m, const glm::dvec3& p) { return glm::vec3(m * glm::dvec4(p, 1.0)); }

class Building : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(shot("corridor_a"))) GTEST_SKIP() << "no shared corridors";
  }
};

TEST_F(Building, TwoCorridorsEndToEndOpenIntoEachOther) {
  auto built = buildModel(modeling::chainLayout({shot("corridor_a"), shot("corridor_c")}), {});
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

TEST_F(Building, ThreeCorridorsWithASideWingRenderAndOpen) {
  modeling::Layout layout = modeling::chainLayout({shot("corridor_b"), shot("corridor_c"), shot("corridor_a")});
  layout.corridors[1].attach = modeling::Attachment{0, modeling::Side::kLeft, 6.0};   // a wing off b's left wall
  layout.corridors[2].attach = modeling::Attachment{0, modeling::Side::kFar, 0.0};    // a continues b
  auto built = buildModel(layout, {});
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

  // Every viewpoint renders and shows the building (the overview sees it whole, from
  // above, on a black background: a few percent of the frame at least).
  engine::RendererOptions options;
  options.forceCpu = true;
  options.validation = engine::RendererOptions::Validation::kOn;
  auto renderer = engine::Renderer::create(options);
  ASSERT_TRUE(renderer.ok()) << renderer.message();
  ASSERT_TRUE((*renderer)->setScene(built->scene).ok());
  ASSERT_GE(built->scene.viewpoints.size(), 6u);
  for (const auto& vp : built->scene.viewpoints) {
    auto image = (*renderer)->renderToImage(engine::cameraFromViewpoint(vp), 320, 180);
    ASSERT_TRUE(image.ok()) << vp.description << ": " << image.message();
    size_t lit = 0;
    for (size_t i = 0; i < image->rgba.size(); i += 4) lit += (image->rgba[i] | image->rgba[i + 1] | image->rgba[i + 2]) != 0;
    EXPECT_GT(lit, image->rgba.size() / 4 / 20) << vp.description;
  }
  EXPECT_EQ((*renderer)->validationMessageCount(), 0u);
}

}  // namespace
}  // namespace pw::editor
