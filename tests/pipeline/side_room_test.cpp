// Side openings (issue 25; modeling/side_room.h) on a random corridor with a doorway in
// its left wall (tests/groundtruth: TUNE seed 0, whose answers say where the opening is).
// The opening is outlined by its four true corners as the photo shows them, as a person
// clicks a doorway's corners, and the model is built from the scene's exact corners with
// the wall opened there and without.
#include <gtest/gtest.h>

#include <algorithm>
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
const fs::path kShot = kDir / "seed_00000.json";

// The doorway's truth: its span along the corridor and its height (model frame).
struct Doorway {
  double z0 = 0, z1 = 0, top = 0;
};

Doorway trueDoorway() {
  std::ifstream in(kShot);
  EXPECT_TRUE(in.good()) << "no " << kShot << " (the build renders it: target groundtruth)";
  const nlohmann::json doc = nlohmann::json::parse(in);
  for (const nlohmann::json& o : doc.at("openings")) {
    if (o.at("kind") == "opening" && o.at("wall") == "left_wall") {
      const double a = o.at("z_m")[0].get<double>(), b = o.at("z_m")[1].get<double>();
      return {std::min(a, b), std::max(a, b), o.at("y_m")[1].get<double>()};
    }
  }
  ADD_FAILURE() << "no doorway in the left wall of " << kShot;
  return {};
}

MeasuredShot measured() {
  auto shot = measureShotFile(kShot);
  EXPECT_TRUE(shot.ok()) << shot.message();
  return shot ? std::move(*shot) : MeasuredShot{};
}

// The doorway's four corners as the photo shows them.
metrology::Cutout doorwayOutline(const metrology::Measurement& m, const Doorway& d, const std::string& name) {
  metrology::Cutout cutout{name, {}, metrology::CutoutShape::kOpening};
  const double x = -0.5 * m.size.widthM;
  for (const glm::dvec3 p : {glm::dvec3(x, 0, d.z1), glm::dvec3(x, 0, d.z0), glm::dvec3(x, d.top, d.z0), glm::dvec3(x, d.top, d.z1)}) {
    cutout.outlinePx.push_back(glm::dvec2(metrology::projectWithMeasurement(m, p)));
  }
  return cutout;
}

Result<BuiltModel> builtWith(std::vector<metrology::Cutout> cutouts) {
  MeasuredShot shot = measured();
  shot.loaded.shot.cutouts = std::move(cutouts);
  return buildModel(chainLayout({kShot}), {shot}, {});
}

BuiltModel built(std::vector<metrology::Cutout> cutouts) {
  auto model = builtWith(std::move(cutouts));
  EXPECT_TRUE(model.ok()) << model.message();
  return model ? std::move(*model) : BuiltModel{};
}

TEST(SideRooms, TheDoorwayIsOpenedWhereItIs) {
  const Doorway truth = trueDoorway();
  const MeasuredShot shot = measured();
  const BuiltModel model = built({doorwayOutline(shot.measurement, truth, "doorway")});
  ASSERT_EQ(model.corridors.size(), 1u);
  ASSERT_EQ(model.corridors[0].rooms.size(), 1u);
  const SideRoom& room = model.corridors[0].rooms[0];
  EXPECT_EQ(room.wall, Surface::kLeftWall);
  // The left wall's s runs along -z (surfaces.h); exact corners give the exact opening.
  EXPECT_NEAR(room.opening.s0, -truth.z1, 1e-6 * model.corridors[0].box.lengthM);
  EXPECT_NEAR(room.opening.s1, -truth.z0, 1e-6 * model.corridors[0].box.lengthM);
  EXPECT_DOUBLE_EQ(room.opening.t0, 0.0);
  EXPECT_NEAR(room.opening.t1, truth.top, 1e-6 * truth.top);
  EXPECT_DOUBLE_EQ(room.depthM, kRoomDepthM);
  // The back wall, floor, ceiling, two ends and the wall's back; the photo sees some of
  // the room through the doorway (seen nearly edge on: the room's nearer end and its floor).
  ASSERT_EQ(room.panels.size(), 6u);
  double seen = 0;
  for (const RoomPanel& panel : room.panels) seen = std::max(seen, panel.seenFraction);
  EXPECT_GT(seen, 0.0);
  bool said = false;
  for (const std::string& line : model.scene.info) said = said || line.rfind("opened: doorway", 0) == 0;
  EXPECT_TRUE(said);
}

TEST(SideRooms, TheWalkGoesThroughTheDoorwayIntoTheRoom) {
  const Doorway truth = trueDoorway();
  const BuiltModel flat = built({}), opened = built({doorwayOutline(measured().measurement, truth, "doorway")});
  const double wallX = -0.5 * opened.corridors[0].box.widthM;
  // From the corridor's middle, at the doorway's middle, straight through the wall at
  // chest height: the flat wall stops the walker; the opened one lets her into the room
  // up to its back wall.
  const glm::vec3 start(0.0f, 1.2f, static_cast<float>(0.5 * (truth.z0 + truth.z1)));
  const glm::vec3 through(static_cast<float>(wallX - 5.0), 0.0f, 0.0f);
  constexpr float kRadius = 0.25f;
  const glm::vec3 stopped = engine::CollisionWorld::fromScene(flat.scene).slideSphere(start, kRadius, through);
  EXPECT_NEAR(stopped.x, wallX + kRadius, 0.01);
  const glm::vec3 walked = engine::CollisionWorld::fromScene(opened.scene).slideSphere(start, kRadius, through);
  EXPECT_NEAR(walked.x, wallX - kRoomDepthM + kRadius, 0.01);
}

TEST(SideRooms, TheModelStillGivesThePhotoBack) {
  engine::RendererOptions options;
  options.forceCpu = true;
  options.validation = engine::RendererOptions::Validation::kOn;
  auto renderer = engine::Renderer::create(options);
  ASSERT_TRUE(renderer.ok()) << renderer.message();
  const cv::Mat photo = cv::imread((kDir / "seed_00000.png").string(), cv::IMREAD_COLOR);
  ASSERT_FALSE(photo.empty());
  const auto psnr = [&](const BuiltModel& model) {
    test::NovelView view{"seed_00000", "photo",
                         photoCamera(model.corridors[0].measurement, photo.cols, photo.rows, glm::dmat4(1.0)), photo};
    std::string error;
    const cv::Mat ours = test::renderView(**renderer, model.scene, view, error);
    EXPECT_FALSE(ours.empty()) << error;
    return ours.empty() ? 0.0 : test::scoreView(ours, photo).psnrDb;
  };
  const double flat = psnr(built({})), opened = psnr(built({doorwayOutline(measured().measurement, trueDoorway(), "doorway")}));
  // Measured: 37.56 dB flat, 37.55 dB opened.
  EXPECT_GT(opened, flat - 0.1) << "flat " << flat << " dB, opened " << opened << " dB";
}

TEST(SideRooms, VrmlAndGltfCarryTheRoom) {
  const BuiltModel model = built({doorwayOutline(measured().measurement, trueDoorway(), "doorway")});
  const fs::path dir = fs::path(PW_BINARY_DIR) / "test-output" / "side_room";
  fs::create_directories(dir);
  ASSERT_TRUE(engine::writeVrml(model.scene, dir / "opened.wrl").ok());
  ASSERT_TRUE(engine::writeGltf(model.scene, dir / "opened.glb").ok());
  for (const char* file : {"opened.wrl", "opened.glb"}) {
    SCOPED_TRACE(file);
    std::vector<std::string> warnings;
    auto scene = engine::loadModel(dir / file, &warnings);
    ASSERT_TRUE(scene.ok()) << scene.message();
    int room = 0, textured = 0;
    for (const engine::Shape& shape : scene->shapes) {
      const bool ours = shape.name.find("room_doorway") != std::string::npos ||
                        (shape.appearance && shape.appearance->texture &&
                         shape.appearance->texture->url.find("room_doorway") != std::string::npos);
      room += ours;
      textured += ours && shape.appearance && shape.appearance->texture;
    }
    EXPECT_EQ(room, 6);
    EXPECT_GE(textured, 1);
  }
}

TEST(SideRooms, AnOutlineOffTheSideWallsOrOverlappingAnotherIsRefusedByName) {
  const MeasuredShot shot = measured();
  const metrology::Measurement& m = shot.measurement;
  // Around a patch of floor in the corridor's middle.
  metrology::Cutout floor{"rug", {}, metrology::CutoutShape::kOpening};
  for (const glm::dvec3 p : {glm::dvec3(-0.3, 0, -1.0), glm::dvec3(0.3, 0, -1.0), glm::dvec3(0.3, 0, -1.6), glm::dvec3(-0.3, 0, -1.6)}) {
    floor.outlinePx.push_back(glm::dvec2(metrology::projectWithMeasurement(m, p)));
  }
  auto refused = builtWith({floor});
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.message().find("cutout \"rug\""), std::string::npos) << refused.message();
  EXPECT_NE(refused.message().find("side wall"), std::string::npos) << refused.message();
  // The doorway twice.
  const Doorway truth = trueDoorway();
  auto twice = builtWith({doorwayOutline(m, truth, "a"), doorwayOutline(m, {truth.z0 + 0.3, truth.z1 + 0.3, truth.top}, "b")});
  ASSERT_FALSE(twice.ok());
  EXPECT_NE(twice.message().find("overlap"), std::string::npos) << twice.message();
}

// Two doorways in one wall: each room reaches half way to the other's doorway, so that
// neither room's end stands inside the other (seen through one doorway, the other's
// room would show its texture there).
TEST(SideRooms, TwoRoomsInOneWallMeetHalfWay) {
  const Doorway truth = trueDoorway();
  const Doorway farther{truth.z0 - 2.0, truth.z0 - 1.2, truth.top};
  const BuiltModel model =
      built({doorwayOutline(measured().measurement, truth, "near"), doorwayOutline(measured().measurement, farther, "far")});
  ASSERT_EQ(model.corridors.at(0).rooms.size(), 2u);
  const auto endZ = [](const SideRoom& room, const std::string& label) {
    for (const RoomPanel& panel : room.panels) {
      if (panel.label == label) return panel.panel.origin.z;
    }
    ADD_FAILURE() << "no " << label;
    return 0.0;
  };
  const SideRoom& nearRoom = model.corridors[0].rooms[0];
  const SideRoom& farRoom = model.corridors[0].rooms[1];
  const double middle = 0.5 * (farther.z1 + truth.z0);
  EXPECT_GE(endZ(nearRoom, "far_end"), middle - 1e-9);
  EXPECT_LE(endZ(farRoom, "near_end"), middle + 1e-9);
}

TEST(SideRooms, AShotFileKeepsAnOpening) {
  auto loaded = loadShot(kShot);
  ASSERT_TRUE(loaded.ok()) << loaded.message();
  metrology::Shot shot = loaded->shot;
  shot.cutouts = {doorwayOutline(measured().measurement, trueDoorway(), "doorway")};
  const fs::path dir = fs::path(PW_BINARY_DIR) / "test-output" / "side_room";
  fs::create_directories(dir);
  ASSERT_TRUE(writeShotFile(dir / "opened.json", shot, loaded->otherFields).ok());
  std::ifstream in(dir / "opened.json");
  const nlohmann::json doc = nlohmann::json::parse(in);
  EXPECT_EQ(doc.at("cutouts").at(0).at("shape"), "opening");
  auto back = readShotFile(dir / "opened.json");
  ASSERT_TRUE(back.ok()) << back.message();
  EXPECT_TRUE(back->cutouts == shot.cutouts);
}

}  // namespace
}  // namespace pw::modeling
