#include "engine/scene/texture_detail.h"
#include "modeling/corridor_model.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "engine/scene/collision.h"
#include "metrology/measure.h"
#include "metrology/rectify.h"

namespace pw::modeling {
namespace {

// corridor_a of the ground truth (tests/groundtruth), its shot part only.
metrology::Shot corridorA() {
  metrology::Shot shot;
  shot.imagePath = std::string(PW_GROUNDTRUTH_DIR) + "/corridor_a.png";
  shot.imageWidth = 800;
  shot.imageHeight = 600;
  shot.focalPx = 692.820323;
  shot.principalPointPx = glm::dvec2(399.5, 299.5);
  shot.cameraHeightM = 1.5;
  shot.cornersPx = {glm::dvec2(340.1154, 235.1667), {458.8846, 235.1667}, {340.1154, 373.7307}, {458.8846, 373.7307},
                    {214.7479, 530.4401},           {584.2521, 530.4401}, {214.7479, 99.3519},  {584.2521, 99.3519}};
  return shot;
}

class CorridorModelTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const metrology::Shot shot = corridorA();
    photo_ = cv::imread(shot.imagePath, cv::IMREAD_COLOR);
    ASSERT_FALSE(photo_.empty()) << "cannot read " << shot.imagePath;
    auto m = metrology::measureCorridor(shot);
    ASSERT_TRUE(m.ok()) << m.message();
    measurement_ = *m;
  }
  cv::Mat photo_;
  metrology::Measurement measurement_;
};

TEST_F(CorridorModelTest, TexturesRunTowardsTheCameraAsFarAsThePhotoShows) {
  auto model = makeCorridorModel("a", photo_, measurement_, false, {});
  ASSERT_TRUE(model.ok()) << model.message();
  // The camera stands 4.5 m before the near corners; the floor is seen to about
  // 3.9 m (where the image's bottom row meets it: depth f h / (v - cv) = 3.45 m).
  EXPECT_GT(model->photoNearM, 0.8);
  EXPECT_LT(model->photoNearM, 4.5);
  // Synthesized (the default): the corridor runs on 3 m behind the camera and is closed
  // there; photo-only: 1 m, open.
  EXPECT_NEAR(model->untexturedNearM, measurement_.pose.positionM.z + 3.0, 1e-9);
  EXPECT_TRUE(model->closed);
  for (const auto& tex : model->textures) {
    ASSERT_TRUE(tex);
    EXPECT_GT(tex->coveredFraction, 0.5);
    EXPECT_GE(tex->image.width, 2);
  }
  ModelOptions photoOnly;
  photoOnly.photoOnly = true;
  auto open = makeCorridorModel("a", photo_, measurement_, false, photoOnly);
  ASSERT_TRUE(open.ok());
  EXPECT_NEAR(open->untexturedNearM, measurement_.pose.positionM.z + 1.0, 1e-9);
  EXPECT_FALSE(open->closed);
  for (const auto& extension : open->extensions) EXPECT_FALSE(extension);
}

// What the photo did not see is synthesized from what it saw of the same surface: the
// texture has no flat mean-colour part, and each surface's strip towards and behind the
// camera carries on from the texture's near edge without a seam.
TEST_F(CorridorModelTest, UnseenPartsContinueTheSurfaceWithoutASeam) {
  auto model = makeCorridorModel("a", photo_, measurement_, false, {});
  ASSERT_TRUE(model.ok());
  ModelOptions photoOnly;
  photoOnly.photoOnly = true;
  auto open = makeCorridorModel("a", photo_, measurement_, false, photoOnly);
  ASSERT_TRUE(open.ok());
  const auto mat = [](const engine::Image& image) {
    return cv::Mat(image.height, image.width, CV_8UC4, const_cast<uint8_t*>(image.rgba.data()));
  };
  for (Surface surface : {Surface::kLeftWall, Surface::kRightWall, Surface::kFloor, Surface::kCeiling}) {
    const int s = static_cast<int>(surface);
    SCOPED_TRACE(surfaceName(surface));
    ASSERT_TRUE(model->extensions[s]);
    const SynthesisStats& stats = model->synthesis[s];
    EXPECT_GT(stats.exemplarColumns, 32);
    EXPECT_GT(stats.filledFraction, 0.05);
    // The photo-only texture's unseen part is one flat colour; the synthesized one is
    // as varied as the part the photo saw (brick walls, a checker floor).
    const SurfaceTexture& filled = *model->textures[s];
    const SurfaceTexture& flat = *open->textures[s];
    ASSERT_EQ(filled.image.width, flat.image.width);
    cv::Mat diff;
    cv::absdiff(mat(filled.image), mat(flat.image), diff);
    cv::Mat changed;
    cv::cvtColor(diff, changed, cv::COLOR_RGBA2GRAY);
    const double changedFraction = cv::countNonZero(changed > 8) / double(changed.total());
    const bool walls = surface == Surface::kLeftWall || surface == Surface::kRightWall;
    if (walls || surface == Surface::kFloor) {  // brick and checker (the ceiling is plain)
      EXPECT_GT(changedFraction, 0.5 * (1.0 - filled.coveredFraction)) << "the filled texels differ from the flat fill";
      cv::Scalar mean, stddev;
      cv::meanStdDev(mat(model->extensions[s]->image), mean, stddev);
      EXPECT_GT(stddev[0], 10.0) << "the strip carries the surface's pattern, not a flat colour";
    }
  }
  // The left wall's strip (columns from the camera's side) meets the texture's first
  // column (the near edge): the last strip column and the first texture column are alike.
  const cv::Mat strip = mat(model->extensions[1]->image), wall = mat(model->textures[1]->image);
  ASSERT_EQ(strip.rows, wall.rows);
  const double seam = cv::norm(strip.col(strip.cols - 1), wall.col(0), cv::NORM_L1) / (4.0 * wall.rows);
  const double within = cv::norm(wall.col(0), wall.col(1), cv::NORM_L1) / (4.0 * wall.rows);
  std::printf("left wall: mean step across the seam %.1f, between the texture's first two columns %.1f\n", seam, within);
  EXPECT_LT(seam, 3 * within + 4);
}

// Each texture's pixel at a model point has the colour the photo has where the
// measured camera sees that point: the texture is cut through the same camera.
TEST_F(CorridorModelTest, TexturePixelsMatchThePhotoThroughTheCamera) {
  auto model = makeCorridorModel("a", photo_, measurement_, false, {});
  ASSERT_TRUE(model.ok()) << model.message();
  const Panel panel = surfacePanel(Surface::kFloor, model->box, model->photoNearM);
  const SurfaceTexture& floor = *model->textures[static_cast<int>(Surface::kFloor)];
  // The texture as the photo shows it: its detail layer divided out (texture_detail.h).
  engine::Texture texture;
  texture.image = std::make_shared<engine::Image>(floor.image);
  if (!floor.detail.empty()) texture.detail = std::make_shared<engine::Image>(floor.detail);
  std::vector<uint8_t> base(floor.image.rgba.size());
  engine::stageBaseAndDetail(texture, base.data());
  // RMS difference between texels and the photo's pixels where the camera sees the
  // texel's model point; `mirror` reads the texture mirrored along s (what a texture
  // cut with one axis reversed would show).
  auto rms = [&](bool mirror) {
    double sumSq = 0;
    int n = 0;
    for (double fs = 0.1; fs < 0.95; fs += 0.1) {
      for (double ft = 0.05; ft < 0.95; ft += 0.05) {
        const double s = floor.rect.s0 + fs * (floor.rect.s1 - floor.rect.s0);
        const double t = floor.rect.t0 + ft * (floor.rect.t1 - floor.rect.t0);
        const glm::dvec3 px = metrology::projectWithMeasurement(measurement_, panel.point(s, t));
        if (px.z <= 0 || px.x < 1 || px.y < 1 || px.x > photo_.cols - 2 || px.y > photo_.rows - 2) continue;
        const double texS = mirror ? 1 - fs : fs;
        const int tx = static_cast<int>(texS * floor.image.width), ty = static_cast<int>((1 - ft) * floor.image.height);
        const uint8_t* texel = base.data() + (static_cast<size_t>(ty) * floor.image.width + tx) * 4;
        const cv::Vec3b photoPx =
            photo_.at<cv::Vec3b>(static_cast<int>(std::lround(px.y)), static_cast<int>(std::lround(px.x)));
        for (int c = 0; c < 3; ++c) {
          const double d = double(texel[c]) - photoPx[2 - c];
          sumSq += d * d;
        }
        n += 3;
      }
    }
    EXPECT_GT(n, 100);
    return std::sqrt(sumSq / std::max(n, 1));
  };
  const double aligned = rms(false), mirrored = rms(true);
  std::printf("floor texture vs photo: RMS %.2f (mirrored: %.2f)\n", aligned, mirrored);
  // Measured 2026-11-29: 9.0 (nearest-pixel sampling on both sides, at the checker
  // floor's edges), mirrored 77.7.
  EXPECT_LT(aligned, 11.0);
  EXPECT_GT(mirrored, 4 * aligned);
}

// `build` and `rectify` cut textures with the same code (metrology/rectify.h): at the
// same resolution the model's far wall is `rectify`'s far wall, texel for texel.
TEST_F(CorridorModelTest, FarWallIsCutAsRectifyCutsIt) {
  ModelOptions options;
  options.pxPerM = 60;
  auto model = makeCorridorModel("a", photo_, measurement_, false, options);
  ASSERT_TRUE(model.ok()) << model.message();
  metrology::RectifyOptions rectifyOptions;
  rectifyOptions.pxPerM = 60;
  auto planes = metrology::rectifyCorridor(photo_, measurement_, rectifyOptions);
  ASSERT_TRUE(planes.ok()) << planes.message();
  const engine::Image& built = model->textures[static_cast<int>(Surface::kFarWall)]->image;
  const cv::Mat& rectified = (*planes)[static_cast<int>(metrology::Plane::kFarWall)].image;
  ASSERT_EQ(built.width, rectified.cols);
  ASSERT_EQ(built.height, rectified.rows);
  int differing = 0, largest = 0;
  for (int y = 0; y < rectified.rows; ++y) {
    for (int x = 0; x < rectified.cols; ++x) {
      const cv::Vec3b bgr = rectified.at<cv::Vec3b>(y, x);
      const uint8_t* rgba = built.pixel(x, y);
      int d = 0;
      for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(rgba[c]) - int(bgr[2 - c])));
      differing += d > 0;
      largest = std::max(largest, d);
    }
  }
  std::printf("far wall, build vs rectify: %d of %d texels differ, by %d at most\n", differing,
              rectified.rows * rectified.cols, largest);
  // Measured: 0 texels differ. The same homography up to rounding (the panel's frame and
  // the corners'): at most 1/255 on a few texels; a texture cut another way (another
  // filter, flipped, shifted by a texel) differs on most of them.
  EXPECT_LE(largest, 1);
  EXPECT_LT(differing, rectified.rows * rectified.cols / 100);
}

TEST_F(CorridorModelTest, SceneHasFivePlanesNearStripsViewpointsAndNoMaterials) {
  auto model = makeCorridorModel("a", photo_, measurement_, false, {});
  ASSERT_TRUE(model.ok());
  const std::vector<metrology::Dimensions> boxes{model->box};
  auto plan = planBuilding(chainLayout({"a.json"}), boxes);
  ASSERT_TRUE(plan.ok());
  const engine::Scene scene = makeBuildingScene({*model}, *plan, {});
  EXPECT_EQ(scene.shapes.size(), 10u);  // five planes, four strips (not the far wall), the near-end wall
  int synthesizedLines = 0;
  for (const std::string& line : scene.info) synthesizedLines += line.rfind("synthesized: ", 0) == 0;
  EXPECT_GE(synthesizedLines, 9) << "the model says which parts are synthesized";
  for (const auto& shape : scene.shapes) EXPECT_FALSE(shape.appearance && shape.appearance->material);
  ASSERT_GE(scene.viewpoints.size(), 4u);
  EXPECT_EQ(scene.viewpoints[0].description, "Photo");
  EXPECT_EQ(scene.viewpoints[3].description, "Overview");
  EXPECT_FALSE(scene.navigation.headlight);
  EXPECT_NEAR(scene.navigation.avatarHeightM, 1.5f, 1e-6f);
  // A person at the Photo viewpoint stands on the floor between walls.
  const auto world = engine::CollisionWorld::fromScene(scene);
  const glm::vec3 eye = scene.viewpoints[0].position;
  auto down = world.raycast(eye, {0, -1, 0}, 10);
  ASSERT_TRUE(down);
  EXPECT_NEAR(down->distance, 1.5f, 0.01f);
  EXPECT_TRUE(world.raycast(eye, {-1, 0, 0}, 10));
  EXPECT_TRUE(world.raycast(eye, {1, 0, 0}, 10));
}

// The Overview is a cutaway from above: the eye is between the walls (so both are seen
// from inside, their drawn side), above the ceiling (seen from behind, not drawn, so it
// does not hide the floor), before the far wall, and the whole model is in view.
TEST_F(CorridorModelTest, OverviewSeesEveryWallFromInsideAndTheWholeModel) {
  auto model = makeCorridorModel("a", photo_, measurement_, false, {});
  ASSERT_TRUE(model.ok());
  auto plan = planBuilding(chainLayout({"a.json"}), std::vector<metrology::Dimensions>{model->box});
  ASSERT_TRUE(plan.ok());
  const engine::Scene scene = makeBuildingScene({*model}, *plan, {});
  ASSERT_GE(scene.viewpoints.size(), 4u);
  ASSERT_EQ(scene.viewpoints[3].description, "Overview");
  const engine::Camera camera = engine::cameraFromViewpoint(scene.viewpoints[3]);
  const glm::vec3 eye = camera.position;  // corridor a's frame is the world
  EXPECT_LT(std::abs(eye.x), 0.5 * model->box.widthM - 0.1) << "between the walls";
  EXPECT_GT(eye.y, model->box.heightM + 0.5) << "above the ceiling";
  EXPECT_GT(eye.z, 0.0) << "behind the near end";
  const engine::Bounds bounds = engine::sceneBounds(scene);
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 corner(i & 1 ? bounds.max.x : bounds.min.x, i & 2 ? bounds.max.y : bounds.min.y,
                           i & 4 ? bounds.max.z : bounds.min.z);
    for (const glm::ivec2 frame : {glm::ivec2(320, 180), glm::ivec2(180, 320)}) {
      const glm::dvec3 px = engine::projectToPixel(camera, frame.x, frame.y, corner);
      EXPECT_GT(px.z, 0.0);
      EXPECT_GE(px.x, -0.5) << "corner " << i;
      EXPECT_LE(px.x, frame.x - 0.5) << "corner " << i;
      EXPECT_GE(px.y, -0.5) << "corner " << i;
      EXPECT_LE(px.y, frame.y - 0.5) << "corner " << i;
    }
  }
}

TEST_F(CorridorModelTest, LitModelHasMaterialsLightsAndHeadlight) {
  ModelOptions options;
  options.lit = true;
  auto model = makeCorridorModel("a", photo_, measurement_, false, options);
  ASSERT_TRUE(model.ok());
  auto plan = planBuilding(chainLayout({"a.json"}), {model->box});
  const engine::Scene scene = makeBuildingScene({*model}, *plan, options);
  for (const auto& shape : scene.shapes) EXPECT_TRUE(shape.appearance && shape.appearance->material);
  EXPECT_GE(scene.lights.size(), 2u);
  EXPECT_TRUE(scene.navigation.headlight);
}

}  // namespace
}  // namespace pw::modeling
