// Building mode without a window: the plan's geometry and snapping (plan.h), and the
// building document (building.h): layouts written and read back, undo, measured sizes.
#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "base/atomic_file.h"
#include "editor/edit/building.h"
#include "editor/edit/plan.h"
#include "tests/support/groundtruth.h"

namespace pw::edit {
namespace {
namespace fs = std::filesystem;
using modeling::Attachment;
using modeling::Layout;
using modeling::LayoutEntry;
using modeling::Side;

constexpr metrology::Dimensions kHall{3.0, 3.2, 14.5};
constexpr metrology::Dimensions kWing{2.4, 2.8, 9.5};

LayoutEntry placed(const std::string& name, glm::dvec3 position, double rotationDeg) {
  LayoutEntry e;
  e.name = name;
  e.shot = name + ".json";
  e.position = position;
  e.rotationDeg = rotationDeg;
  return e;
}

// A hall at the origin and a wing placed apart, to its right.
Layout twoApart() {
  Layout layout;
  layout.corridors = {placed("hall", {0, 0, 0}, 0), placed("wing", {8, 0, 3}, 0)};
  return layout;
}

fs::path outputDir() {
  const fs::path dir = fs::path(PW_BINARY_DIR) / "test-output" / "edit_plan";
  fs::create_directories(dir);
  return dir;
}

TEST(Plan, PosesAndFootprintsFollowTheLayoutsConventions) {
  Layout layout = twoApart();
  layout.corridors[1].rotationDeg = 90;  // counter-clockwise seen from above: the far wall towards -x
  const auto world = placeCorridors(layout, {kHall, kWing});
  const PlanPose hall = poseOf(world[0]), wing = poseOf(world[1]);
  EXPECT_NEAR(hall.nearCentre.x, 0, 1e-12);
  EXPECT_NEAR(hall.rotationDeg, 0, 1e-12);
  EXPECT_NEAR(wing.nearCentre.x, 8, 1e-12);
  EXPECT_NEAR(wing.nearCentre.y, 3, 1e-12);
  EXPECT_NEAR(wing.rotationDeg, 90, 1e-9);
  const auto hallCorners = footprintCorners(world[0], kHall);
  EXPECT_NEAR(hallCorners[2].x, 1.5, 1e-12);     // far right
  EXPECT_NEAR(hallCorners[2].y, -14.5, 1e-12);
  const auto wingCorners = footprintCorners(world[1], kWing);
  EXPECT_NEAR(wingCorners[2].x, 8 - 9.5, 1e-9);  // its far wall 9.5 m to the left
  EXPECT_EQ(corridorAt(world, {kHall, kWing}, {0.5, -7}), 0);
  EXPECT_EQ(corridorAt(world, {kHall, kWing}, {4, 3.5}), 1);
  EXPECT_EQ(corridorAt(world, {kHall, kWing}, {-5, 5}), -1);
}

TEST(Plan, ASecondCorridorDraggedNearTheFirstsFarEndSnapsToItsFarWall) {
  const Layout layout = twoApart();
  const std::vector<metrology::Dimensions> boxes = {kHall, kWing};
  const auto world = placeCorridors(layout, boxes);
  // Its near end 0.3 m short of the far wall and 0.1 m off the centre line.
  const auto snap = findSnap(layout, boxes, world, 1, {{0.1, -14.2}, 0}, 0.5);
  ASSERT_TRUE(snap.has_value());
  EXPECT_EQ(snap->attach.to, 0);
  EXPECT_EQ(snap->attach.side, Side::kFar);
  EXPECT_EQ(snap->attach.offsetM, 0.0);  // within kCentreSnapM: centred
  EXPECT_NEAR(snap->pose.nearCentre.x, 0, 1e-12);
  EXPECT_NEAR(snap->pose.nearCentre.y, -14.5, 1e-12);
  EXPECT_NEAR(snap->distanceM, std::hypot(0.1, 0.3), 1e-12);
  // Further off the centre line, the offset is kept.
  const auto aside = findSnap(layout, boxes, world, 1, {{0.8, -14.6}, 0}, 0.5);
  ASSERT_TRUE(aside.has_value());
  EXPECT_EQ(aside->attach.side, Side::kFar);
  EXPECT_NEAR(aside->attach.offsetM, 0.8, 1e-12);
  // Too far: nothing.
  EXPECT_FALSE(findSnap(layout, boxes, world, 1, {{0.0, -15.2}, 0}, 0.5).has_value());

  int index = -1;
  const Layout attached = attachCorridor(layout, 1, snap->attach, &index);
  EXPECT_EQ(index, 1);
  ASSERT_TRUE(attached.corridors[1].attach.has_value());
  const auto after = placeCorridors(attached, boxes);
  EXPECT_NEAR(poseOf(after[1]).nearCentre.y, -14.5, 1e-12);
  // modeling's own plan agrees, and finds the openings.
  auto plan = modeling::planBuilding(attached, boxes);
  ASSERT_TRUE(plan.ok()) << plan.message();
  EXPECT_EQ(plan->openings.size(), 2u);
  EXPECT_NEAR(glm::length(glm::dvec3(plan->worldFromCorridor[1][3]) - glm::dvec3(after[1][3])), 0, 1e-12);
}

TEST(Plan, ANearEndDraggedNearASideWallSnapsToItAtTheOffsetFromTheNearEnd) {
  const Layout layout = twoApart();
  const std::vector<metrology::Dimensions> boxes = {kHall, kWing};
  const auto world = placeCorridors(layout, boxes);
  const auto left = findSnap(layout, boxes, world, 1, {{-1.8, -6.0}, 0}, 0.5);
  ASSERT_TRUE(left.has_value());
  EXPECT_EQ(left->attach.side, Side::kLeft);
  EXPECT_NEAR(left->attach.offsetM, 6.0, 1e-12);
  EXPECT_NEAR(left->pose.nearCentre.x, -1.5, 1e-12);
  EXPECT_NEAR(left->pose.nearCentre.y, -6.0, 1e-12);
  EXPECT_NEAR(left->pose.rotationDeg, 90, 1e-9);  // it leads away to the left
  const auto right = findSnap(layout, boxes, world, 1, {{1.3, -10.0}, 0}, 0.5);
  ASSERT_TRUE(right.has_value());
  EXPECT_EQ(right->attach.side, Side::kRight);
  EXPECT_NEAR(right->attach.offsetM, 10.0, 1e-12);
  EXPECT_NEAR(right->pose.rotationDeg, -90, 1e-9);
  // Near the hall's near end the opening would not fit: the offset stops half the wing's width in.
  const auto end = findSnap(layout, boxes, world, 1, {{1.6, -0.9}, 0}, 0.5);
  ASSERT_TRUE(end.has_value());
  EXPECT_EQ(end->attach.side, Side::kRight);
  EXPECT_NEAR(end->attach.offsetM, 1.2, 1e-12);
  EXPECT_TRUE(modeling::planBuilding(attachCorridor(layout, 1, end->attach, nullptr), boxes).ok());
}

TEST(Plan, ACorridorDoesNotSnapToOneThatMovesWithIt) {
  Layout layout = twoApart();
  layout.corridors.push_back(placed("end", {0, 0, 0}, 0));
  layout.corridors[2].attach = Attachment{1, Side::kFar, 0.0};  // end hangs off the wing
  const std::vector<metrology::Dimensions> boxes = {kHall, kWing, kWing};
  const auto world = placeCorridors(layout, boxes);
  EXPECT_EQ(movesWith(layout, 1), (std::vector<bool>{false, true, true}));
  // The wing dragged onto its own guest's far wall: no snap to it (the hall is too far).
  const PlanPose endFar{{8, 3 - 9.5 - 9.5 + 0.1}, 0};
  EXPECT_FALSE(findSnap(layout, boxes, world, 1, endFar, 0.5).has_value());
  // The hall dragged there does snap, to the end corridor.
  const auto hall = findSnap(layout, boxes, world, 0, endFar, 0.5);
  ASSERT_TRUE(hall.has_value());
  EXPECT_EQ(hall->attach.to, 2);
}

TEST(Plan, AttachingToACorridorListedLaterListsTheHostsFirst) {
  Layout layout = twoApart();
  layout.corridors.push_back(placed("end", {0, 0, 0}, 0));
  layout.corridors[2].attach = Attachment{0, Side::kFar, 0.0};  // end on the hall
  int index = -1;
  // The hall goes onto the wing's left wall: wing, hall, end.
  const Layout sorted = attachCorridor(layout, 0, {1, Side::kLeft, 4.0}, &index);
  ASSERT_EQ(sorted.corridors.size(), 3u);
  EXPECT_EQ(sorted.corridors[0].name, "wing");
  EXPECT_EQ(sorted.corridors[1].name, "hall");
  EXPECT_EQ(sorted.corridors[2].name, "end");
  EXPECT_EQ(index, 1);
  EXPECT_EQ(sorted.corridors[1].attach->to, 0);
  EXPECT_EQ(sorted.corridors[2].attach->to, 1);
  EXPECT_TRUE(modeling::planBuilding(sorted, {kWing, kHall, kWing}).ok());
  // A cycle is refused: the wing cannot attach to the hall now.
  const Layout refused = attachCorridor(sorted, 0, {1, Side::kFar, 0.0}, nullptr);
  EXPECT_TRUE(sameLayout(refused, sorted));
}

TEST(Plan, TurningByQuarterTurnsKeepsWholeDegreesAndAGuestsAttachment) {
  Layout layout = twoApart();
  const auto world = placeCorridors(layout, {kHall, kWing});
  Layout turned = layout;
  for (int k = 0; k < 4; ++k) turned = rotateCorridor(turned, world, 1, 90.0);
  EXPECT_EQ(turned.corridors[1].rotationDeg, 0.0);
  EXPECT_EQ(rotateCorridor(layout, world, 1, 90.0).corridors[1].rotationDeg, 90.0);
  EXPECT_EQ(rotateCorridor(layout, world, 1, -90.0).corridors[1].rotationDeg, -90.0);
  EXPECT_EQ(rotateCorridor(layout, world, 1, 270.0).corridors[1].rotationDeg, -90.0);
  EXPECT_EQ(rotateCorridor(layout, world, 1, 180.0).corridors[1].position, layout.corridors[1].position);
  // An attached corridor turned (issue 23's finding: R detached it): it stays attached,
  // and its host turns, carrying it.
  layout.corridors[1].attach = Attachment{0, Side::kLeft, 5.0};
  const auto attachedWorld = placeCorridors(layout, {kHall, kWing});
  const Layout kept = rotateCorridor(layout, attachedWorld, 1, -90.0);
  ASSERT_TRUE(kept.corridors[1].attach.has_value());
  EXPECT_EQ(kept.corridors[1].attach->to, 0);
  EXPECT_EQ(kept.corridors[1].attach->side, Side::kLeft);
  EXPECT_EQ(kept.corridors[1].attach->offsetM, 5.0);
  EXPECT_EQ(kept.corridors[0].rotationDeg, layout.corridors[0].rotationDeg - 90.0);
  EXPECT_EQ(kept.corridors[0].position, layout.corridors[0].position);
  EXPECT_TRUE(sameLayout(rotateCorridor(kept, placeCorridors(kept, {kHall, kWing}), 1, 90.0), layout));
}

TEST(Plan, OpeningsAreWhereAnAttachedNearEndMeetsItsHostsWall) {
  Layout layout = twoApart();
  const std::vector<metrology::Dimensions> boxes = {kHall, kWing};
  EXPECT_FALSE(openingInHost(layout, boxes, placeCorridors(layout, boxes), 1).has_value());  // placed
  layout.corridors[1].attach = Attachment{0, Side::kFar, 1.0};  // sticks out 0.7 m beyond the right wall
  auto far = openingInHost(layout, boxes, placeCorridors(layout, boxes), 1);
  ASSERT_TRUE(far.has_value());
  EXPECT_NEAR((*far)[0].x, -0.2, 1e-12);
  EXPECT_NEAR((*far)[1].x, 1.5, 1e-12);
  EXPECT_NEAR((*far)[0].y, -14.5, 1e-12);
  layout.corridors[1].attach = Attachment{0, Side::kLeft, 5.0};
  auto left = openingInHost(layout, boxes, placeCorridors(layout, boxes), 1);
  ASSERT_TRUE(left.has_value());
  EXPECT_NEAR((*left)[0].x, -1.5, 1e-12);
  EXPECT_NEAR((*left)[0].y, -3.8, 1e-12);
  EXPECT_NEAR((*left)[1].y, -6.2, 1e-12);
}

TEST(Plan, RemovingACorridorLeavesTheOnesOnItWhereTheyStand) {
  Layout layout = twoApart();
  layout.corridors.push_back(placed("end", {0, 0, 0}, 0));
  layout.corridors[1].attach = Attachment{0, Side::kRight, 6.0};  // wing on the hall
  layout.corridors[2].attach = Attachment{1, Side::kFar, 0.0};    // end on the wing
  const std::vector<metrology::Dimensions> boxes = {kHall, kWing, kWing};
  const auto world = placeCorridors(layout, boxes);
  const Layout removed = removeCorridor(layout, world, 0);
  ASSERT_EQ(removed.corridors.size(), 2u);
  EXPECT_EQ(removed.corridors[0].name, "wing");
  EXPECT_FALSE(removed.corridors[0].attach.has_value());  // placed where it stood
  EXPECT_NEAR(removed.corridors[0].position.x, 1.5, 1e-12);
  EXPECT_NEAR(removed.corridors[0].position.z, -6.0, 1e-12);
  EXPECT_EQ(removed.corridors[0].rotationDeg, -90.0);
  ASSERT_TRUE(removed.corridors[1].attach.has_value());  // still on the wing, renumbered
  EXPECT_EQ(removed.corridors[1].attach->to, 0);
  const auto after = placeCorridors(removed, {kWing, kWing});
  EXPECT_NEAR(glm::length(glm::dvec3(after[1][3]) - glm::dvec3(world[2][3])), 0, 1e-9);
  // The last corridor stays.
  EXPECT_EQ(removeCorridor(removeCorridor(removed, after, 0), placeCorridors(removeCorridor(removed, after, 0), {kWing}), 0)
                .corridors.size(),
            1u);
}

TEST(Plan, ALayoutWrittenAndReadAgainIsTheSameWithTheFieldsPhotowalkDoesNotRead) {
  const fs::path dir = outputDir();
  const fs::path path = dir / "written.layout.json";
  Layout layout = twoApart();
  layout.corridors[0].shot = dir / "shots" / "hall.json";
  layout.corridors[1].shot = dir / "wing.json";
  layout.corridors[1].attach = Attachment{0, Side::kRight, 6.25};
  layout.corridors[0].rotationDeg = 12.5;
  layout.corridors[0].position = {0.125, 0.0, -3.0};
  layout.corridors[0].otherFields = {{"colour", "red"}, {"notes", {1, 2}}};
  layout.otherFields = {{"title", "the house"}};
  ASSERT_TRUE(modeling::writeLayoutFile(path, layout).ok());
  auto read = modeling::readLayoutFile(path);
  ASSERT_TRUE(read.ok()) << read.message();
  EXPECT_TRUE(sameLayout(*read, layout));
  EXPECT_EQ(read->corridors[0].otherFields["colour"], "red");
  EXPECT_EQ(read->otherFields["title"], "the house");
  // Shots are written relative to the layout's folder.
  const nlohmann::json doc = nlohmann::json::parse(*readFile(path));
  EXPECT_EQ(doc["corridors"][0]["shot"], "shots/hall.json");
  EXPECT_EQ(doc["corridors"][1]["attach"]["to"], "hall");
  EXPECT_EQ(doc["corridors"][1]["attach"]["side"], "right");
  EXPECT_FALSE(doc["corridors"][1].contains("position"));  // attached: placed by its host
  // Written again from what was read: the same bytes.
  ASSERT_TRUE(modeling::writeLayoutFile(dir / "again.layout.json", *read).ok());
  EXPECT_EQ(*readFile(dir / "again.layout.json"), *readFile(path));
}

// A layout of two ground-truth shots, copied beside it.
fs::path groundTruthLayout(const fs::path& dir) {
  fs::create_directories(dir);
  for (const char* name : {"corridor_b", "corridor_a"}) {
    const groundtruth::GroundTruth truth = groundtruth::loadGroundTruth(name);
    fs::copy_file(truth.image, dir / truth.image.filename(), fs::copy_options::overwrite_existing);
    fs::copy_file(truth.shot, dir / truth.shot.filename(), fs::copy_options::overwrite_existing);
  }
  const fs::path path = dir / "building.json";
  std::ofstream(path) << R"({"title": "two corridors", "corridors": [
    {"name": "hall", "shot": "corridor_b.json", "position": [0, 0, 0], "rotation_deg": 0, "colour": "blue"},
    {"name": "wing", "shot": "corridor_a.json", "position": [8, 0, 2], "rotation_deg": 0}]})";
  return path;
}

TEST(Building, OpensTheShotsMeasuresThemAndSavesTheLayoutWithUndo) {
  const fs::path path = groundTruthLayout(outputDir() / "building");
  auto building = Building::open(path);
  ASSERT_TRUE(building.ok()) << building.message();
  ASSERT_EQ(building->layout().corridors.size(), 2u);
  const auto boxes = building->boxes();
  EXPECT_NEAR(boxes[0].widthM, 3.0, 0.05);
  EXPECT_NEAR(boxes[0].lengthM, 14.5, 0.3);
  EXPECT_NEAR(boxes[1].widthM, 2.4, 0.05);
  EXPECT_TRUE(building->measured(0) && building->measured(1));
  EXPECT_FALSE(building->dirty());

  const auto world = placeCorridors(building->layout(), boxes);
  const auto snap = findSnap(building->layout(), boxes, world, 1, {{0.05, -boxes[0].lengthM + 0.2}, 0}, 0.5);
  ASSERT_TRUE(snap.has_value());
  building->apply(attachCorridor(building->layout(), 1, snap->attach, nullptr), "attach wing");
  EXPECT_TRUE(building->dirty());
  ASSERT_TRUE(building->save(nullptr).ok());
  EXPECT_FALSE(building->dirty());
  auto read = modeling::readLayoutFile(path);
  ASSERT_TRUE(read.ok()) << read.message();
  ASSERT_TRUE(read->corridors[1].attach.has_value());
  EXPECT_EQ(read->corridors[1].attach->side, Side::kFar);
  EXPECT_EQ(read->corridors[1].otherFields, nlohmann::json::object());
  EXPECT_EQ(read->corridors[0].otherFields["colour"], "blue");
  EXPECT_EQ(read->otherFields["title"], "two corridors");

  ASSERT_TRUE(building->undo());
  EXPECT_FALSE(building->layout().corridors[1].attach.has_value());
  EXPECT_TRUE(building->dirty());
  ASSERT_TRUE(building->redo());
  EXPECT_FALSE(building->dirty());

  // Both corridors as the walk takes them: the whole building builds.
  auto model = building->buildModel(nullptr);
  ASSERT_TRUE(model.ok()) << model.message();
  EXPECT_EQ(model->plan.openings.size(), 2u);
  EXPECT_EQ(model->scene.viewpoints.back().description, "wing: entrance");
}

TEST(Building, ALentShotsEditedCornersChangeTheCorridorsSizeInThePlan) {
  const fs::path path = groundTruthLayout(outputDir() / "lent");
  auto building = Building::open(path);
  ASSERT_TRUE(building.ok()) << building.message();
  const double before = building->boxes()[0].lengthM;
  const fs::path shotPath = building->layout().corridors[0].shot;
  std::optional<Document> doc = building->lend(shotPath);
  ASSERT_TRUE(doc.has_value());
  EXPECT_FALSE(building->lend(shotPath).has_value());  // one at a time
  // The far wall's corners moved towards the vanishing point: a longer corridor.
  metrology::Shot shot = doc->shot();
  const glm::dvec2 centre = 0.25 * (shot.cornersPx[0] + shot.cornersPx[1] + shot.cornersPx[2] + shot.cornersPx[3]);
  for (int k = 0; k < 4; ++k) shot.cornersPx[k] = centre + 0.9 * (shot.cornersPx[k] - centre);
  doc->apply(shot, "shrink the far wall");
  building->remeasure(&*doc);
  EXPECT_GT(building->boxes()[0].lengthM, before + 0.5);
  EXPECT_FALSE(building->dirty());  // the layout is unchanged; the shot's change is the document's
  building->giveBack(shotPath, std::move(*doc));
  EXPECT_TRUE(building->dirty());
  EXPECT_TRUE(building->shot(shotPath)->history().canUndo());  // its undo history came back with it
}

TEST(Building, APhotoAddedIsPlacedBesideTheOthersAndSavedAsAShot) {
  const fs::path dir = outputDir() / "added";
  const fs::path path = groundTruthLayout(dir);
  const groundtruth::GroundTruth truth = groundtruth::loadGroundTruth("corridor_c");
  fs::copy_file(truth.image, dir / "third.png", fs::copy_options::overwrite_existing);
  fs::remove(dir / "third.shot.json");
  auto building = Building::open(path);
  ASSERT_TRUE(building.ok()) << building.message();
  auto added = building->addShot(dir / "third.png");
  ASSERT_TRUE(added.ok()) << added.message();
  EXPECT_EQ(*added, 2);
  EXPECT_EQ(building->layout().corridors[2].name, "third");
  const auto boxes = building->boxes();
  const auto world = placeCorridors(building->layout(), boxes);
  // Right of everything else.
  for (int i = 0; i < 2; ++i) {
    for (const glm::dvec2& c : footprintCorners(world[i], boxes[i])) {
      for (const glm::dvec2& d : footprintCorners(world[2], boxes[2])) EXPECT_LT(c.x, d.x);
    }
  }
  EXPECT_FALSE(building->addShot(dir / "nothing.png").ok());
  ASSERT_TRUE(building->save(nullptr).ok());
  EXPECT_TRUE(fs::exists(dir / "third.shot.json"));
  auto read = modeling::readLayoutFile(path);
  ASSERT_TRUE(read.ok()) << read.message();
  ASSERT_EQ(read->corridors.size(), 3u);
  EXPECT_EQ(read->corridors[2].shot, dir / "third.shot.json");
  ASSERT_TRUE(building->undo());
  EXPECT_EQ(building->layout().corridors.size(), 2u);
}

}  // namespace
}  // namespace pw::edit
