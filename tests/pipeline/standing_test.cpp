// Objects stood up (issue 25, part 3) on a random corridor with a person in it
// (tests/groundtruth: TUNE seed 0, rendered with its object-id mask and its novel views;
// seed_00000_standing.json is its shot with a rectangle drawn 4 px around the person, as
// a person would). The model is built from the scene's exact corners twice: as before
// (the person painted flat on the floor and the wall) and with the person stood up.
// bench/standing_views.py gives the figures over many scenes.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "engine/gltf/gltf_writer.h"
#include "engine/gpu/renderer.h"
#include "engine/io/model_io.h"
#include "engine/scene/collision.h"
#include "engine/vrml/vrml_writer.h"
#include "modeling/pipeline.h"
#include "modeling/shot_file.h"
#include "tests/support/novel_views.h"

namespace pw::modeling {
namespace {
namespace fs = std::filesystem;

const fs::path kDir = fs::path(PW_GROUNDTRUTH_DIR) / "random";
const fs::path kFlatShot = kDir / "seed_00000.json";
const fs::path kStandingShot = kDir / "seed_00000_standing.json";

// The person's answers: true height, where she stands (the middle of her footprint,
// model frame) and her footprint's depth.
struct Person {
  double heightM = 0, depthM = 0;
  glm::dvec3 placeM{0.0};
};

Person truePerson() {
  std::ifstream in(kStandingShot);
  EXPECT_TRUE(in.good()) << "no " << kStandingShot << " (the build renders it: target groundtruth)";
  const nlohmann::json doc = nlohmann::json::parse(in);
  for (const nlohmann::json& o : doc.at("objects")) {
    if (o.at("kind") == "person") {
      return {o.at("size_m")[1].get<double>(), o.at("size_m")[2].get<double>(),
              {o.at("place_m")[0].get<double>(), 0.0, o.at("place_m")[2].get<double>()}};
    }
  }
  ADD_FAILURE() << "no person in " << kStandingShot;
  return {};
}

BuiltModel built(const fs::path& shot) {
  auto model = buildModel(chainLayout({shot}), {});
  EXPECT_TRUE(model.ok()) << model.message();
  return model ? std::move(*model) : BuiltModel{};
}

std::unique_ptr<engine::Renderer> cpuRenderer() {
  engine::RendererOptions options;
  options.forceCpu = true;
  options.validation = engine::RendererOptions::Validation::kOn;
  auto renderer = engine::Renderer::create(options);
  EXPECT_TRUE(renderer.ok()) << renderer.message();
  return renderer ? std::move(*renderer) : nullptr;
}

// PSNR of the model seen from the photo's camera against the photo.
double photoPsnr(engine::Renderer& renderer, const BuiltModel& model, const fs::path& shot) {
  const cv::Mat photo = cv::imread((kDir / "seed_00000.png").string(), cv::IMREAD_COLOR);
  EXPECT_FALSE(photo.empty());
  test::NovelView view{"seed_00000", "photo",
                       photoCamera(model.corridors[0].measurement, photo.cols, photo.rows, glm::dmat4(1.0)), photo};
  std::string error;
  const cv::Mat ours = test::renderView(renderer, model.scene, view, error);
  EXPECT_FALSE(ours.empty()) << error << " (" << shot << ")";
  return ours.empty() ? 0.0 : test::scoreView(ours, photo).psnrDb;
}

TEST(StandingObjects, APersonStandsWhereSheStandsAndAsTallAsSheIs) {
  const Person person = truePerson();
  const BuiltModel model = built(kStandingShot);
  ASSERT_EQ(model.corridors.size(), 1u);
  ASSERT_EQ(model.corridors[0].standing.size(), 1u);
  const StandingObject& cut = model.corridors[0].standing[0];
  EXPECT_EQ(cut.name, "person_8");
  // Her lowest pixel is the front of her footprint: the foot is that far before its
  // middle, towards the camera. Measured: 1.9404 m (true 1.9452); foot 0.11 m from the
  // middle of her 0.32 m deep footprint.
  EXPECT_NEAR(cut.heightM, person.heightM, 0.01 * person.heightM);
  EXPECT_LT(glm::length(cut.footM - person.placeM), 0.6 * person.depthM);
  EXPECT_NEAR(cut.faces.at(0).cornersM[0].y, 0.0, 1e-9);
  EXPECT_GT(cut.widthM, 0.3);
  EXPECT_LT(cut.widthM, 1.0);
  // Upright, facing the photo's camera.
  const glm::dvec3 eye = model.corridors[0].measurement.pose.positionM;
  EXPECT_NEAR(cut.faces.at(0).normal.y, 0.0, 1e-12);
  EXPECT_GT(glm::dot(cut.faces.at(0).normal, glm::normalize(glm::dvec3(eye.x, 0.0, eye.z) - cut.footM)), 0.999);
  // The texture's alpha is the person: opaque in her middle, clear in the corners.
  const engine::Image& image = cut.faces.at(0).image;
  ASSERT_GT(image.width, 10);
  const auto alphaAt = [&](double s, double t) {
    const int x = std::clamp(static_cast<int>(s * image.width), 0, image.width - 1);
    const int y = std::clamp(static_cast<int>((1.0 - t) * image.height), 0, image.height - 1);
    return image.rgba[(static_cast<size_t>(y) * image.width + x) * 4 + 3];
  };
  EXPECT_EQ(alphaAt(0.5, 0.7), 255);  // her body
  EXPECT_EQ(alphaAt(0.02, 0.98), 0);
  EXPECT_EQ(alphaAt(0.98, 0.02), 0);
  // The model says what it stood up.
  bool said = false;
  for (const std::string& line : model.scene.info) said = said || line.rfind("stood up: person_8", 0) == 0;
  EXPECT_TRUE(said);
}

TEST(StandingObjects, TheModelStillGivesThePhotoBackAndStandsHerUpElsewhere) {
  auto renderer = cpuRenderer();
  ASSERT_TRUE(renderer);
  const BuiltModel flat = built(kFlatShot), standing = built(kStandingShot);
  // From the photo's camera: measured 37.56 dB flat, 37.62 dB stood up (the cut-out is
  // read as the photo was seen, as the surfaces are).
  const double flatPhoto = photoPsnr(*renderer, flat, kFlatShot), standingPhoto = photoPsnr(*renderer, standing, kStandingShot);
  EXPECT_GT(standingPhoto, flatPhoto - 0.1) << "flat " << flatPhoto << " dB, stood up " << standingPhoto << " dB";
  // A quarter in, turned to the left wall, where she stands: measured 20.61 dB flat,
  // 22.88 dB stood up.
  const test::NovelView turned = test::loadNovelView(kDir, "seed_00000", "turned");
  std::string error;
  const cv::Mat flatView = test::renderView(*renderer, flat.scene, turned, error);
  ASSERT_FALSE(flatView.empty()) << error;
  const cv::Mat standingView = test::renderView(*renderer, standing.scene, turned, error);
  ASSERT_FALSE(standingView.empty()) << error;
  const double flatPsnr = test::scoreView(flatView, turned.truth).psnrDb;
  const double standingPsnr = test::scoreView(standingView, turned.truth).psnrDb;
  EXPECT_GT(standingPsnr, flatPsnr + 1.5) << "flat " << flatPsnr << " dB, stood up " << standingPsnr << " dB";
  const fs::path out = fs::path(PW_BINARY_DIR) / "test-output" / "standing";
  fs::create_directories(out);
  cv::imwrite((out / "turned_flat.png").string(), flatView);
  cv::imwrite((out / "turned_standing.png").string(), standingView);
}

// A lamp hanging on a rod near the photo's camera (TUNE seed 0's lamp 14), outlined 4 px
// around its box as the photo shows it, up to the ceiling where it hangs: stood up as a
// hanging cut-out, from the ceiling down to the lamp's foot, where it hangs.
TEST(StandingObjects, AHangingLampHangsWhereItHangs) {
  std::ifstream in(kFlatShot);
  const nlohmann::json doc = nlohmann::json::parse(in);
  const nlohmann::json* lamp = nullptr;
  for (const nlohmann::json& o : doc.at("objects")) {
    if (o.at("id") == 14) lamp = &o;
  }
  ASSERT_TRUE(lamp && lamp->at("kind") == "lamp") << "no lamp 14 in " << kFlatShot;
  const glm::dvec3 place(lamp->at("place_m")[0].get<double>(), lamp->at("place_m")[1].get<double>(),
                         lamp->at("place_m")[2].get<double>());
  const double drop = lamp->at("size_m")[1].get<double>(), half = 0.5 * lamp->at("size_m")[0].get<double>();
  auto shot = measureShotFile(kFlatShot);
  ASSERT_TRUE(shot.ok()) << shot.message();
  const metrology::Measurement& m = shot->measurement;
  glm::dvec2 lo(1e300), hi(-1e300);
  for (int k = 0; k < 8; ++k) {
    const glm::dvec3 corner(place.x + (k & 1 ? half : -half), k & 2 ? place.y + drop : place.y, place.z + (k & 4 ? half : -half));
    const glm::dvec2 px(metrology::projectWithMeasurement(m, corner));
    lo = glm::min(lo, px), hi = glm::max(hi, px);
  }
  lo -= glm::dvec2(4.0), hi += glm::dvec2(4.0);
  metrology::Cutout outline{"lamp", {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}}, metrology::CutoutShape::kHanging};
  shot->loaded.shot.cutouts = {outline};
  auto model = buildModel(chainLayout({kFlatShot}), {*shot}, {});
  ASSERT_TRUE(model.ok()) << model.message();
  ASSERT_EQ(model->corridors[0].standing.size(), 1u);
  const StandingObject& cut = model->corridors[0].standing[0];
  EXPECT_EQ(cut.shape, metrology::CutoutShape::kHanging);
  // Its top at the ceiling, as far down as the lamp; under it, the lamp's place. Measured:
  // 0.813 m high (true 0.755: GrabCut's mask runs a little below the lamp), 0.24 m from its
  // place along the floor (the outline's top is 4 px above the rod's: nearer the camera).
  const double ceiling = model->corridors[0].box.heightM;
  EXPECT_NEAR(cut.faces.at(0).cornersM[2].y, ceiling, 1e-9);
  EXPECT_NEAR(cut.heightM, drop, 0.12 * drop);
  EXPECT_LT(glm::length(glm::dvec2(cut.footM.x - place.x, cut.footM.z - place.z)), 0.35);
  bool said = false;
  for (const std::string& line : model->scene.info) said = said || line.find("hanging from the ceiling") != std::string::npos;
  EXPECT_TRUE(said);
  // The outline's top above the photo: the lamp is left painted, by name, and the model
  // says so; it still builds.
  metrology::Cutout offTop = outline;
  offTop.outlinePx[0].y = offTop.outlinePx[1].y = -5;
  shot->loaded.shot.cutouts = {offTop};
  auto refused = buildModel(chainLayout({kFlatShot}), {*shot}, {});
  ASSERT_TRUE(refused.ok()) << refused.message();
  EXPECT_TRUE(refused->corridors[0].standing.empty());
  ASSERT_EQ(refused->corridors[0].leftPainted.size(), 1u);
  EXPECT_NE(refused->corridors[0].leftPainted[0].find("top edge"), std::string::npos) << refused->corridors[0].leftPainted[0];
  said = false;
  for (const std::string& line : refused->scene.info) said = said || line.rfind("left painted: cutout \"" + offTop.name + "\"", 0) == 0;
  EXPECT_TRUE(said);
}

TEST(StandingObjects, TheWalkStopsAtHer) {
  const BuiltModel model = built(kStandingShot);
  const StandingObject& cut = model.corridors[0].standing.at(0);
  const engine::CollisionWorld world = engine::CollisionWorld::fromScene(model.scene);
  // From 1 m before her, on the camera's side, walking 1.6 m straight through her at
  // chest height (the far wall is 0.9 m behind her).
  const glm::vec3 start(cut.footM + 1.0 * cut.faces.at(0).normal + glm::dvec3(0, 1.2, 0));
  const glm::vec3 through(-1.6 * cut.faces.at(0).normal);
  constexpr float kRadius = 0.25f;
  const glm::vec3 end = world.slideSphere(start, kRadius, through);
  const double before = glm::dot(glm::dvec3(end) - cut.footM, cut.faces.at(0).normal);
  EXPECT_GE(before, kRadius - 1e-3) << "the walker passed through her";
  EXPECT_LT(before, kRadius + 0.05) << "the walker stopped short of her";
  // Without her, the same walk goes on.
  const engine::CollisionWorld empty = engine::CollisionWorld::fromScene(built(kFlatShot).scene);
  EXPECT_LT(glm::dot(glm::dvec3(empty.slideSphere(start, kRadius, through)) - cut.footM, cut.faces.at(0).normal), -0.5);
}

TEST(StandingObjects, VrmlAndGltfCarryHerWithHerAlpha) {
  const BuiltModel model = built(kStandingShot);
  const fs::path dir = fs::path(PW_BINARY_DIR) / "test-output" / "standing";
  fs::create_directories(dir);
  ASSERT_TRUE(engine::writeVrml(model.scene, dir / "standing.wrl").ok());
  ASSERT_TRUE(engine::writeGltf(model.scene, dir / "standing.glb").ok());
  for (const char* file : {"standing.wrl", "standing.glb"}) {
    SCOPED_TRACE(file);
    std::vector<std::string> warnings;
    auto scene = engine::loadModel(dir / file, &warnings);
    ASSERT_TRUE(scene.ok()) << scene.message();
    const engine::Shape* cut = nullptr;
    for (const engine::Shape& shape : scene->shapes) {
      if (shape.appearance && shape.appearance->texture && shape.appearance->texture->url.find("standing_person_8") != std::string::npos) {
        cut = &shape;
      }
      if (!cut && shape.name.find("standing_person_8") != std::string::npos) cut = &shape;
    }
    ASSERT_NE(cut, nullptr);
    ASSERT_TRUE(cut->appearance && cut->appearance->texture && cut->appearance->texture->image);
    const engine::Image& image = *cut->appearance->texture->image;
    int clear = 0, opaque = 0;
    for (size_t i = 3; i < image.rgba.size(); i += 4) clear += image.rgba[i] == 0, opaque += image.rgba[i] == 255;
    EXPECT_GT(clear, 0);
    EXPECT_GT(opaque, 0);
  }
}

// The editor's preview rebuilds the model as a corner moves: the cut-outs (GrabCut's
// masks and the fill) are kept for the same photo and outlines, and what is stood up
// from them is what is stood up without the cache; new outlines or another photo cut
// again.
TEST(StandingObjects, CutOutsAreKeptWhileTheCornersMove) {
  auto loaded = loadShot(kStandingShot);
  ASSERT_TRUE(loaded.ok()) << loaded.message();
  const cv::Mat& photo = loaded->image;
  const metrology::Shot shot = loaded->shot;
  CutOutCache cache;
  metrology::Shot moved = shot;
  for (int step = 0; step < 3; ++step) {
    moved.cornersPx[metrology::P5] += glm::dvec2(0.7, -0.3);  // a drag's steps
    auto measured = metrology::measureCorridor(moved);
    ASSERT_TRUE(measured.ok()) << measured.message();
    auto cached = standUpObjects(photo, *measured, moved.cutouts, &cache);
    auto fresh = standUpObjects(photo, *measured, moved.cutouts);
    ASSERT_TRUE(cached.ok() && fresh.ok());
    ASSERT_EQ(cached->objects.size(), 1u);
    EXPECT_EQ(cached->objects[0].heightM, fresh->objects[0].heightM);
    EXPECT_EQ(cached->objects[0].faces.at(0).image.rgba, fresh->objects[0].faces.at(0).image.rgba);
    EXPECT_EQ(cv::norm(cached->behind, fresh->behind, cv::NORM_INF), 0.0);
  }
  EXPECT_EQ(cache.made(), 1) << "GrabCut and the fill once for three corner moves";
  // The editor's check when an outline is closed: the objects alone, as they are with
  // the fill, and no fill.
  auto measuredNow = metrology::measureCorridor(moved);
  ASSERT_TRUE(measuredNow.ok());
  auto alone = standUpObjects(photo, *measuredNow, moved.cutouts, &cache, StandUpParts::kObjectsOnly);
  auto withFill = standUpObjects(photo, *measuredNow, moved.cutouts);
  ASSERT_TRUE(alone.ok() && withFill.ok());
  EXPECT_TRUE(alone->behind.empty());
  EXPECT_EQ(alone->objects[0].faces.at(0).image.rgba, withFill->objects[0].faces.at(0).image.rgba);
  EXPECT_EQ(cache.made(), 1) << "the check does not use the cache";
  // Another outline: cut again.
  metrology::Shot outlined = moved;
  outlined.cutouts[0].outlinePx[0] += glm::dvec2(-2, 0);
  auto measured = metrology::measureCorridor(outlined);
  ASSERT_TRUE(measured.ok());
  ASSERT_TRUE(standUpObjects(photo, *measured, outlined.cutouts, &cache).ok());
  EXPECT_EQ(cache.made(), 2);
  // Another photo of the same size at the same address: cut again.
  cv::Mat changed = photo.clone();
  auto first = standUpObjects(changed, *measured, outlined.cutouts, &cache);
  ASSERT_TRUE(first.ok());
  EXPECT_EQ(cache.made(), 3);
  changed(cv::Rect(0, 0, 40, 40)).setTo(cv::Scalar(255, 0, 0));
  ASSERT_TRUE(standUpObjects(changed, *measured, outlined.cutouts, &cache).ok());
  EXPECT_EQ(cache.made(), 4) << "the same address and size, other pixels";
}

TEST(StandingObjects, ShotFilesKeepCutoutsAndBadOnesSayWhy) {
  auto shot = readShotFile(kStandingShot);
  ASSERT_TRUE(shot.ok()) << shot.message();
  ASSERT_EQ(shot->cutouts.size(), 1u);
  const fs::path dir = fs::path(PW_BINARY_DIR) / "test-output" / "standing";
  fs::create_directories(dir);
  ASSERT_TRUE(writeShotFile(dir / "kept.json", *shot).ok());
  auto again = readShotFile(dir / "kept.json");
  ASSERT_TRUE(again.ok()) << again.message();
  EXPECT_EQ(again->cutouts, shot->cutouts);

  auto loaded = loadShot(kStandingShot);
  ASSERT_TRUE(loaded.ok()) << loaded.message();
  auto measured = measureShotFile(kStandingShot);
  ASSERT_TRUE(measured.ok()) << measured.message();
  const cv::Mat& photo = loaded->image;
  const auto standUpOne = [&](std::vector<glm::dvec2> outline) {
    return standUpObjects(photo, measured->measurement, {metrology::Cutout{"box", std::move(outline)}});
  };
  // An object that cannot stand up is left painted, the reason naming it.
  const auto leftPainted = [](const Result<StoodUp>& cut) {
    return cut.ok() && cut->objects.empty() && cut->leftPainted.size() == 1 ? cut->leftPainted[0] : std::string("(stood up or failed)");
  };
  const double w = photo.cols, h = photo.rows;
  // Off the photo's bottom edge: its foot is not in the photo.
  auto cut = standUpOne({{200, h - 60}, {260, h - 60}, {260, h + 5}, {200, h + 5}});
  EXPECT_NE(leftPainted(cut).find("cutout \"box\": it runs off the photo's bottom edge"), std::string::npos) << leftPainted(cut);
  // Above the horizon: on the ceiling, it does not stand on the floor.
  cut = standUpOne({{w / 2 - 20, 2}, {w / 2 + 20, 2}, {w / 2 + 20, 30}, {w / 2 - 20, 30}});
  EXPECT_NE(leftPainted(cut).find("above the horizon"), std::string::npos) << leftPainted(cut);
  // Wholly outside the photo: the outline itself is wrong, an error.
  cut = standUpOne({{w + 10, 10}, {w + 50, 10}, {w + 50, 50}});
  ASSERT_FALSE(cut.ok());
  EXPECT_NE(cut.message().find("is not inside the"), std::string::npos) << cut.message();
  // A cutout file error names the field.
  {
    nlohmann::json doc = nlohmann::json::parse(std::ifstream(kStandingShot));
    doc["image"] = (kDir / "seed_00000.png").string();
    doc["cutouts"][0]["outline_px"] = nlohmann::json::array({nlohmann::json::array({1, 2}), nlohmann::json::array({3, 4})});
    std::ofstream(dir / "bad.json") << doc.dump();
  }
  auto bad = readShotFile(dir / "bad.json");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.message().find("cutouts[0]: its outline needs 3 points or more"), std::string::npos) << bad.message();
}

}  // namespace
}  // namespace pw::modeling
