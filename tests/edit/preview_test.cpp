// The 3D preview's parts without a window: the shot in a reduced photo's pixels, the
// orbit camera's arithmetic, and the builder's worker (on lavapipe, offscreen).
#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "editor/edit/preview.h"
#include "editor/edit/preview_build.h"
#include "metrology/measure.h"
#include "modeling/shot_file.h"
#include "tests/support/groundtruth.h"

namespace pw::edit {
namespace {

metrology::Shot corridorB() {
  auto loaded = modeling::loadShot(groundtruth::groundTruthShot("corridor_b"));
  EXPECT_TRUE(loaded.ok()) << loaded.message();
  return loaded ? loaded->shot : metrology::Shot{};
}

TEST(PreviewBuild, TheShotInAReducedPhotosPixelsMeasuresTheSameCorridor) {
  const metrology::Shot shot = corridorB();
  const metrology::Shot half = scaledShot(shot, {512, 384});
  EXPECT_EQ(half.imageWidth, 512);
  EXPECT_DOUBLE_EQ(half.focalPx, shot.focalPx / 2);
  EXPECT_DOUBLE_EQ(half.cornersPx[metrology::P5].x, (shot.cornersPx[metrology::P5].x + 0.5) / 2 - 0.5);
  EXPECT_DOUBLE_EQ(half.principalPoint().y, (shot.principalPoint().y + 0.5) / 2 - 0.5);
  auto full = metrology::measureCorridor(shot), reduced = metrology::measureCorridor(half);
  ASSERT_TRUE(full.ok() && reduced.ok());
  EXPECT_NEAR(reduced->size.widthM, full->size.widthM, 1e-6);
  EXPECT_NEAR(reduced->size.heightM, full->size.heightM, 1e-6);
  EXPECT_NEAR(reduced->size.lengthM, full->size.lengthM, 1e-6);
}

TEST(PreviewBuild, APhotoIsReducedToItsLongestSideAndASmallOneIsKept) {
  const cv::Mat big(3000, 4000, CV_8UC3, cv::Scalar(10, 20, 30));
  const cv::Mat reduced = reducePhoto(big, 1024);
  EXPECT_EQ(reduced.cols, 1024);
  EXPECT_EQ(reduced.rows, 768);
  EXPECT_EQ(reduced.at<cv::Vec3b>(100, 100), cv::Vec3b(10, 20, 30));
  const cv::Mat small(768, 1024, CV_8UC3);
  EXPECT_EQ(reducePhoto(small, 1024).data, small.data);
}

TEST(PreviewBuild, OnlyANewerResultOfTheOpenDocumentAndAFullOneOfTheShotAsItIsTakeThePlaceOfTheOneShown) {
  const metrology::Shot now = corridorB();
  metrology::Shot earlier = now;
  earlier.cornersPx[metrology::P5].x -= 3;
  const auto done = [](uint64_t id, uint64_t document, const metrology::Shot& shot, PreviewResolution from) {
    PreviewBuilder::Done d;
    d.id = id;
    d.documentId = document;
    d.shot = shot;
    d.from = from;
    return d;
  };
  const auto kReduced = PreviewResolution::kReduced, kFull = PreviewResolution::kFull;
  const ShownBuild shown{2, 5, kReduced};
  EXPECT_TRUE(takesPlaceOf(done(1, 2, now, kFull), 2, std::nullopt, now));    // the first model
  EXPECT_FALSE(takesPlaceOf(done(6, 1, now, kFull), 2, shown, now));          // of a document since closed
  EXPECT_FALSE(takesPlaceOf(done(4, 2, now, kFull), 2, shown, now));          // older than the one shown
  EXPECT_TRUE(takesPlaceOf(done(5, 2, now, kFull), 2, shown, now));           // the full one after its reduced one
  EXPECT_FALSE(takesPlaceOf(done(5, 2, now, kReduced), 2, ShownBuild{2, 5, kFull}, now));  // not the other way
  EXPECT_FALSE(takesPlaceOf(done(6, 2, earlier, kFull), 2, shown, now));      // full, but the shot has changed since
  EXPECT_TRUE(takesPlaceOf(done(6, 2, earlier, kReduced), 2, shown, now));    // a drag's earlier step: followed
  EXPECT_TRUE(takesPlaceOf(done(1, 3, now, kFull), 3, shown, now));           // a new document's first
}

TEST(PreviewCamera, OrbitingKeepsTheCentreWhereItIsInThePicture) {
  engine::Camera camera;
  camera.position = {0.4f, 1.6f, 5.5f};
  camera.orientation = engine::lookAtOrientation(camera.position, {0.2f, 1.4f, -3.0f});
  const glm::vec3 centre(0.1f, 1.5f, -4.0f);
  const glm::dvec3 before = engine::projectToPixel(camera, 640, 480, centre);
  const float distance = glm::length(camera.position - centre);
  orbitCamera(camera, centre, 0.7f, 0.3f);
  const glm::dvec3 after = engine::projectToPixel(camera, 640, 480, centre);
  EXPECT_NEAR(after.x, before.x, 1e-2);
  EXPECT_NEAR(after.y, before.y, 1e-2);
  EXPECT_NEAR(glm::length(camera.position - centre), distance, 1e-4);
  EXPECT_GT(camera.position.y, 1.6f + 1.0f);  // risen, looking down
  EXPECT_LT(engine::forwardOf(camera).y, -0.2f);
  // However far it is pitched, never over the top.
  orbitCamera(camera, centre, 0.0f, 10.0f);
  EXPECT_NEAR(std::asin(engine::forwardOf(camera).y), -glm::radians(85.0f), 1e-3);
  orbitCamera(camera, centre, 0.0f, -20.0f);
  EXPECT_NEAR(std::asin(engine::forwardOf(camera).y), glm::radians(85.0f), 1e-3);
}

// Issue 23's findings: the orbited preview was rolled with the photo and a small model in
// the void. Turning levels the camera; leaving the photo's camera frames the whole model.
TEST(PreviewCamera, OrbitingFromARolledCameraLevelsIt) {
  engine::Camera camera;
  camera.position = {0.0f, 1.5f, 0.0f};
  camera.orientation = engine::lookAtOrientation(camera.position, {0.0f, 1.4f, -5.0f}) *
                       glm::angleAxis(glm::radians(8.0f), glm::vec3(0, 0, 1));  // rolled 8 degrees
  const glm::vec3 right = glm::normalize(camera.orientation) * glm::vec3(1, 0, 0);
  ASSERT_GT(std::abs(right.y), 0.1f);
  orbitCamera(camera, {0.0f, 1.4f, -5.0f}, 0.05f, 0.0f);
  const glm::vec3 levelled = glm::normalize(camera.orientation) * glm::vec3(1, 0, 0);
  EXPECT_NEAR(levelled.y, 0.0f, 1e-5f);
}

TEST(PreviewCamera, FramingShowsTheWholeModelFromOutsideItAboveThePhotosSide) {
  engine::Bounds bounds;
  bounds.add(glm::vec3(-1.2f, 0.0f, -9.5f));
  bounds.add(glm::vec3(1.2f, 2.8f, 3.0f));
  engine::Camera photo;
  photo.position = {0.1f, 1.5f, 0.5f};
  photo.orientation = engine::lookAtOrientation(photo.position, {0.0f, 1.4f, -9.0f});
  const engine::Camera framed = framedCamera(bounds, photo);
  EXPECT_GT(framed.position.z, bounds.max.z);  // outside, on the photo's side
  EXPECT_GT(framed.position.y, bounds.max.y);  // above
  const glm::vec3 levelled = glm::normalize(framed.orientation) * glm::vec3(1, 0, 0);
  EXPECT_NEAR(levelled.y, 0.0f, 1e-5f);
  glm::dvec2 lo(1e9), hi(-1e9);
  for (int k = 0; k < 8; ++k) {
    const glm::vec3 corner(k & 1 ? bounds.max.x : bounds.min.x, k & 2 ? bounds.max.y : bounds.min.y,
                           k & 4 ? bounds.max.z : bounds.min.z);
    const glm::dvec3 p = engine::projectToPixel(framed, 640, 480, corner);
    ASSERT_GT(p.z, 0.0) << k;
    lo = glm::min(lo, glm::dvec2(p)), hi = glm::max(hi, glm::dvec2(p));
  }
  EXPECT_GE(lo.x, 0.0);
  EXPECT_GE(lo.y, 0.0);
  EXPECT_LE(hi.x, 640.0);
  EXPECT_LE(hi.y, 480.0);
  EXPECT_GT(std::max((hi.x - lo.x) / 640.0, (hi.y - lo.y) / 480.0), 0.4);  // not a small model in the void
}

TEST(PreviewCamera, DollyingScalesTheDistanceToTheCentreDownToATenthOfAMetre) {
  engine::Camera camera;
  camera.position = {0.0f, 0.0f, 10.0f};
  dollyCamera(camera, glm::vec3(0.0f), 0.5f);
  EXPECT_NEAR(camera.position.z, 5.0f, 1e-5);
  dollyCamera(camera, glm::vec3(0.0f), 1e-6f);
  EXPECT_NEAR(camera.position.z, 0.1f, 1e-5);
}

TEST(PreviewBuilder, AFullRequestOnABigPhotoGivesTheReducedModelThenTheFullOne) {
  auto renderer = engine::Renderer::create({});
  ASSERT_TRUE(renderer.ok()) << renderer.message();
  const metrology::Shot shot = corridorB();
  const cv::Mat photo = cv::imread(groundtruth::loadGroundTruth("corridor_b").image.string());
  ASSERT_FALSE(photo.empty());
  // A reduced side of 512: corridor_b (1024 x 768) is then a "big" photo.
  PreviewBuilder builder(**renderer, 512);
  builder.request({7, 1, shot, photo, false, true});
  std::vector<PreviewBuilder::Done> done;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (done.size() < 2 && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    for (PreviewBuilder::Done& d : builder.takeDone()) done.push_back(std::move(d));
  }
  ASSERT_EQ(done.size(), 2u);
  EXPECT_FALSE(builder.busy());
  EXPECT_EQ(done[0].from, PreviewResolution::kReduced);
  EXPECT_EQ(done[1].from, PreviewResolution::kFull);
  for (const PreviewBuilder::Done& d : done) {
    EXPECT_EQ(d.id, 7u);
    ASSERT_TRUE(d.model.ok()) << d.model.message();
    // The Photo viewpoint: the camera of the shot (0.4 m right, 1.6 m up, 5.5 m before the near corners).
    EXPECT_NEAR(d.model->photoCamera.position.x, 0.4, 0.02);
    EXPECT_NEAR(d.model->photoCamera.position.y, 1.6, 0.02);
  }
  EXPECT_EQ(done[0].model->photoSizePx, glm::ivec2(512, 384));
  EXPECT_EQ(done[1].model->photoSizePx, glm::ivec2(1024, 768));
}

TEST(PreviewBuilder, CornersThatCannotBeMeasuredGiveAnErrorNotAModel) {
  auto renderer = engine::Renderer::create({});
  ASSERT_TRUE(renderer.ok()) << renderer.message();
  metrology::Shot shot = corridorB();
  shot.cornersPx[metrology::P5] = shot.cornersPx[metrology::P3];  // the floor collapses
  shot.cornersPx[metrology::P6] = shot.cornersPx[metrology::P4];
  const cv::Mat photo(768, 1024, CV_8UC3, cv::Scalar(90, 90, 90));
  auto model = buildPreviewModel(**renderer, shot, photo, PreviewResolution::kFull);
  ASSERT_FALSE(model.ok());
  EXPECT_FALSE(model.message().empty());
}

}  // namespace
}  // namespace pw::edit
