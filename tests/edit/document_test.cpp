// The editor's document without a window: opening photos and shot files, undo and
// redo as whole shots, dirty tracking, Save.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "base/atomic_file.h"
#include "editor/edit/document.h"
#include "metrology/measure.h"
#include "metrology/shot_check.h"
#include "tests/detect/synthetic_corridor.h"
#include "tests/support/groundtruth.h"

namespace pw::edit {
namespace {
namespace fs = std::filesystem;
using metrology::Shot;

fs::path outputDir() {
  const fs::path dir = fs::path(PW_BINARY_DIR) / "test-output" / "edit_document";
  fs::create_directories(dir);
  return dir;
}

std::string bytesOf(const fs::path& path) {
  auto text = readFile(path);
  return text ? *text : std::string("<unreadable>");
}

TEST(Document, PhotoWithoutCornersGetsThemFromDetectionWithConfidences) {
  const groundtruth::GroundTruth truth = groundtruth::loadGroundTruth("corridor_b");
  auto doc = Document::open(truth.image);
  ASSERT_TRUE(doc.ok()) << doc.message();
  EXPECT_TRUE(doc->dirty());  // never saved
  EXPECT_EQ(doc->path(), truth.image.parent_path() / "corridor_b.shot.json");
  EXPECT_EQ(doc->shot().imageWidth, truth.imageWidth);
  ASSERT_TRUE(doc->shot().cameraHeightM.has_value());
  EXPECT_EQ(*doc->shot().cameraHeightM, kDefaultCameraHeightM);
  // P5..P8 at the nearest cross-section whose four corners are inside the photo (detect's
  // default; the answers have them on the scene's painted band): inside, one of them at
  // the 1% margin from the photo's border.
  const double margin = 0.01 * std::min(truth.imageWidth, truth.imageHeight);
  double nearestBorder = 1e9;
  for (int k = metrology::P5; k <= metrology::P8; ++k) {
    const glm::dvec2 p = doc->shot().cornersPx[k];
    nearestBorder = std::min({nearestBorder, p.x, p.y, truth.imageWidth - 1 - p.x, truth.imageHeight - 1 - p.y});
  }
  EXPECT_GE(nearestBorder, margin - 0.01);
  EXPECT_LE(nearestBorder, margin + 0.5);
  for (int k = 0; k < metrology::kCornerCount; ++k) {
    // Detection on this scene: the far wall within 0.6 px of the exact projections
    // (measured 0.39 at most, P1's v).
    if (k < metrology::P5) {
      EXPECT_NEAR(doc->shot().cornersPx[k].x, truth.cornersPx[k].x, 0.6) << metrology::cornerName(k);
      EXPECT_NEAR(doc->shot().cornersPx[k].y, truth.cornersPx[k].y, 0.6) << metrology::cornerName(k);
    }
    ASSERT_TRUE(doc->detectionConfidence(k).has_value());
    EXPECT_GT(*doc->detectionConfidence(k), 0.0);
    EXPECT_LE(*doc->detectionConfidence(k), 1.0);
  }
  ASSERT_FALSE(doc->notes().empty());
  EXPECT_NE(doc->notes().front().find("corners detected (confidence"), std::string::npos) << doc->notes().front();

  // A corner moved is no longer the detection's: its confidence goes.
  Shot moved = doc->shot();
  moved.cornersPx[metrology::P5].x += 1;
  doc->apply(moved, "move P5");
  EXPECT_FALSE(doc->detectionConfidence(metrology::P5).has_value());
  EXPECT_TRUE(doc->detectionConfidence(metrology::P6).has_value());
  doc->undo();
  EXPECT_TRUE(doc->detectionConfidence(metrology::P5).has_value());
}

TEST(Document, PhotoWithNoCorridorGetsADefaultBoxThatMeasures) {
  const fs::path photo = outputDir() / "flat_grey.png";
  ASSERT_TRUE(cv::imwrite(photo.string(), cv::Mat(480, 640, CV_8UC3, cv::Scalar(128, 128, 128))));
  auto doc = Document::open(photo, {outputDir() / "grey.json"});
  ASSERT_TRUE(doc.ok()) << doc.message();
  EXPECT_EQ(doc->path(), outputDir() / "grey.json");
  EXPECT_EQ(doc->shot().cornersPx, defaultCorners(640, 480));
  EXPECT_EQ(doc->shot().focalPx, 0.8 * 640);
  ASSERT_FALSE(doc->notes().empty());
  EXPECT_NE(doc->notes().front().find("no corridor found"), std::string::npos) << doc->notes().front();
  EXPECT_FALSE(doc->detectionConfidence(0).has_value());
  // The default box is a valid shot: it passes the checks and measures.
  EXPECT_TRUE(metrology::checkShot(doc->shot()).ok()) << metrology::checkShot(doc->shot()).message();
  auto m = metrology::measureCorridor(doc->shot());
  ASSERT_TRUE(m.ok()) << m.message();
  EXPECT_GT(m->size.lengthM, 0.0);
  // ... but it is a placeholder, saying so, until a corner is moved.
  const auto noted = [&](const std::string& words) {
    const auto notes = doc->notes();
    return std::any_of(notes.begin(), notes.end(), [&](const std::string& n) { return n.find(words) != std::string::npos; });
  };
  EXPECT_TRUE(doc->isPlaceholderBox());
  EXPECT_TRUE(noted("a default box from the image size, not the corridor's"));
  // The assumptions' notes go once their values are set, and come back when they are
  // set back to the assumed ones.
  EXPECT_TRUE(noted("camera height assumed 1.60 m"));
  EXPECT_TRUE(noted("focal length assumed 512 px"));
  Shot set = doc->shot();
  set.cameraHeightM = 1.45;
  set.focalPx = 600;
  doc->apply(set, "camera");
  EXPECT_FALSE(noted("camera height assumed"));
  EXPECT_FALSE(noted("focal length assumed"));
  EXPECT_TRUE(doc->isPlaceholderBox());  // the camera set, the box is still the placeholder
  set.cornersPx[metrology::P1] += glm::dvec2(5, 3);
  doc->apply(set, "move P1");
  EXPECT_FALSE(doc->isPlaceholderBox());
  EXPECT_FALSE(noted("not the corridor's"));
  doc->undo();
  doc->undo();
  EXPECT_TRUE(noted("camera height assumed 1.60 m"));
  EXPECT_TRUE(noted("focal length assumed 512 px"));
  EXPECT_TRUE(doc->isPlaceholderBox());
}

// Detection unsure of its box (clutter_1: detect's exit 3): a suggestion, shown as one,
// until a corner is moved; a sure one (corridor_b) and a shot file's are not.
TEST(Document, AnUnsureDetectionIsASuggestionUntilACornerMoves) {
  auto unsure = Document::open(groundtruth::loadGroundTruth("clutter_1").image);
  ASSERT_TRUE(unsure.ok()) << unsure.message();
  ASSERT_TRUE(unsure->detectionConfidence(0).has_value()) << "clutter_1: a box should be detected";
  EXPECT_TRUE(unsure->isSuggestedBox());
  EXPECT_FALSE(unsure->isPlaceholderBox());
  Shot moved = unsure->shot();
  moved.cornersPx[metrology::P2] += glm::dvec2(1, 0);
  unsure->apply(moved, "move P2");
  EXPECT_FALSE(unsure->isSuggestedBox());
  unsure->undo();
  EXPECT_TRUE(unsure->isSuggestedBox());
  auto sure = Document::open(groundtruth::loadGroundTruth("corridor_b").image);
  ASSERT_TRUE(sure.ok());
  EXPECT_FALSE(sure->isSuggestedBox());
  auto file = Document::open(groundtruth::loadGroundTruth("clutter_1").shot);
  ASSERT_TRUE(file.ok());
  EXPECT_FALSE(file->isSuggestedBox());
}

// A shot file with detection's report (as `detect -o` writes it, and Save for a photo the
// editor detected): a box detection was unsure of opens as a suggestion, with its doubts
// in the notes and each corner's confidence, for as long as the corners are where
// detection put them; a report of a sure box gives the confidences only; one without the
// corners' px (written before them) is not read.
TEST(Document, ADetectedShotFileOpensAsDetectionLeftIt) {
  const fs::path dir = outputDir() / "detected_file";
  fs::remove_all(dir);
  fs::create_directories(dir);
  auto unsure = Document::open(groundtruth::loadGroundTruth("clutter_1").image);
  ASSERT_TRUE(unsure.ok()) << unsure.message();
  ASSERT_TRUE(unsure->isSuggestedBox()) << "clutter_1: detection should be unsure of its box";
  const fs::path unsureFile = dir / "unsure.shot.json";
  ASSERT_TRUE(unsure->saveCopy(unsureFile).ok());
  const nlohmann::json written = nlohmann::json::parse(bytesOf(unsureFile));
  ASSERT_TRUE(written.contains("detection")) << written.dump();
  EXPECT_FALSE(written["detection"]["confident"].get<bool>());

  auto reopened = Document::open(unsureFile);
  ASSERT_TRUE(reopened.ok()) << reopened.message();
  EXPECT_TRUE(reopened->isSuggestedBox());
  const std::vector<std::string> notes = reopened->notes();
  for (const auto& doubt : written["detection"]["doubts"]) {
    EXPECT_NE(std::find(notes.begin(), notes.end(), "detection unsure: " + doubt.get<std::string>()), notes.end())
        << doubt;
  }
  for (int k = 0; k < metrology::kCornerCount; ++k) {
    ASSERT_TRUE(reopened->detectionConfidence(k).has_value()) << metrology::cornerName(k);
    EXPECT_EQ(*reopened->detectionConfidence(k), *unsure->detectionConfidence(k)) << metrology::cornerName(k);
  }
  // A corner moved and saved: no longer a suggestion when opened again; the moved
  // corner has no confidence, the others keep theirs.
  Shot moved = reopened->shot();
  moved.cornersPx[metrology::P2] += glm::dvec2(3, 0);
  reopened->apply(moved, "move P2");
  EXPECT_FALSE(reopened->isSuggestedBox());
  ASSERT_TRUE(reopened->save().ok());
  auto edited = Document::open(unsureFile);
  ASSERT_TRUE(edited.ok()) << edited.message();
  EXPECT_FALSE(edited->isSuggestedBox());
  EXPECT_FALSE(edited->detectionConfidence(metrology::P2).has_value());
  EXPECT_TRUE(edited->detectionConfidence(metrology::P1).has_value());

  // A sure box: its confidences, no suggestion.
  auto sure = Document::open(groundtruth::loadGroundTruth("corridor_b").image);
  ASSERT_TRUE(sure.ok());
  const fs::path sureFile = dir / "sure.shot.json";
  ASSERT_TRUE(sure->saveCopy(sureFile).ok());
  auto sureAgain = Document::open(sureFile);
  ASSERT_TRUE(sureAgain.ok()) << sureAgain.message();
  EXPECT_FALSE(sureAgain->isSuggestedBox());
  EXPECT_TRUE(sureAgain->detectionConfidence(metrology::P4).has_value());

  // A report without the corners' px (detect before they were written): not read.
  nlohmann::json older = written;
  for (auto& corner : older["detection"]["corners"]) corner.erase("px");
  const fs::path olderFile = dir / "older.shot.json";
  ASSERT_TRUE(writeFileAtomic(olderFile, older.dump(2)).ok());
  auto olderDoc = Document::open(olderFile);
  ASSERT_TRUE(olderDoc.ok()) << olderDoc.message();
  EXPECT_FALSE(olderDoc->isSuggestedBox());
  EXPECT_FALSE(olderDoc->detectionConfidence(metrology::P1).has_value());
}

// E in the editor: corners a person put roughly (each 15 px off) fitted to the photo's
// edges from where they are, as one undo step, with their confidences shown again.
TEST(Document, FitCornersBringsARoughBoxOntoThePhotosEdges) {
  const groundtruth::GroundTruth truth = groundtruth::loadGroundTruth("corridor_g");
  auto doc = Document::open(truth.image);
  ASSERT_TRUE(doc.ok()) << doc.message();
  Shot rough = doc->shot();
  rough.focalPx = truth.focalPx;
  for (int k = 0; k < metrology::kCornerCount; ++k) {
    const double a = 0.7 * k + 0.3;
    rough.cornersPx[k] = truth.cornersPx[k] + 15.0 * glm::dvec2(std::cos(a), std::sin(a));
  }
  doc->apply(rough, "drag");
  const size_t steps = doc->history().size();
  const Document::FitResult fit = doc->fitCorners();
  EXPECT_TRUE(fit.moved) << fit.message;
  EXPECT_NE(fit.message.find("moved up to"), std::string::npos) << fit.message;
  for (int k = 0; k < 4; ++k) {
    EXPECT_LT(glm::length(doc->shot().cornersPx[k] - truth.cornersPx[k]), 2.0) << metrology::cornerName(k);
    EXPECT_TRUE(doc->detectionConfidence(k).has_value());
  }
  EXPECT_EQ(doc->history().size(), steps + 1);
  ASSERT_TRUE(doc->undo());
  EXPECT_EQ(doc->shot().cornersPx, rough.cornersPx);
}

// The fit reads the photo through the lens the shot has (set in the camera panel, or
// a calibrated camera's) and keeps it; a shot without one takes the lens the photo's
// straight lines show, as the corners were fitted through it.
TEST(Document, FitCornersKeepsTheShotsLensOrTakesTheOneFound) {
  const fs::path distorted = fs::path(PW_BINARY_DIR) / "groundtruth-distorted";
  std::ifstream in(distorted / "corridor_a_k020.json");
  const nlohmann::json truthFile = nlohmann::json::parse(in, nullptr, false);
  ASSERT_TRUE(truthFile.is_object()) << "no groundtruth-distorted/corridor_a_k020.json";
  auto doc = Document::open(distorted / "corridor_a_k020.png");
  ASSERT_TRUE(doc.ok()) << doc.message();
  std::array<glm::dvec2, metrology::kCornerCount> truth{};
  Shot rough = doc->shot();
  rough.focalPx = truthFile["focal_px"].get<double>();
  for (int k = 0; k < metrology::kCornerCount; ++k) {
    const auto& p = truthFile["corners_px"][metrology::cornerName(k)];
    truth[k] = {p[0].get<double>(), p[1].get<double>()};
    const double a = 0.7 * k + 0.3;
    rough.cornersPx[k] = truth[k] + 10.0 * glm::dvec2(std::cos(a), std::sin(a));
  }
  const metrology::RadialDistortion lens{truthFile["distortion"]["k1"].get<double>(), 0.0};
  for (const bool given : {true, false}) {
    rough.distortion = given ? std::optional(lens) : std::nullopt;
    doc->apply(rough, "drag");
    const Document::FitResult fit = doc->fitCorners();
    ASSERT_TRUE(fit.moved) << fit.message;
    ASSERT_TRUE(doc->shot().distortion.has_value()) << fit.message;
    if (given) {
      EXPECT_EQ(*doc->shot().distortion, lens);
      EXPECT_EQ(fit.message.find("found from the photo's straight lines"), std::string::npos) << fit.message;
    } else {
      EXPECT_NEAR(doc->shot().distortion->k1, lens.k1, 0.02);
      EXPECT_NE(fit.message.find("found from the photo's straight lines"), std::string::npos) << fit.message;
    }
    for (int k = 0; k < 4; ++k) {
      EXPECT_LT(glm::length(doc->shot().cornersPx[k] - truth[k]), 1.5) << metrology::cornerName(k) << (given ? " (lens given)" : "");
    }
    ASSERT_TRUE(doc->undo());
    EXPECT_EQ(doc->shot().distortion, rough.distortion);
  }
}

// detect's file for a photo with vanishing points but no box opens its photo, with a
// starting box along the points, and saves to that file.
TEST(Document, AVanishingPointsFileOpensItsPhotoWithABoxAlongThem) {
  const fs::path photo = outputDir() / "road.png", file = outputDir() / "road.json";
  ASSERT_TRUE(cv::imwrite(photo.string(), metrology::detect::testing::drawRoadScene()));
  std::ofstream(file) << R"({"image": "road.png", "focal_px": 700, "detection": {"found": false, "reason": "x"}})";
  auto doc = Document::open(file);
  ASSERT_TRUE(doc.ok()) << doc.message();
  EXPECT_EQ(doc->path(), file);
  EXPECT_NE(doc->shot().cornersPx, defaultCorners(800, 600));
  bool said = false;
  for (const std::string& note : doc->notes()) said |= note.find("along the photo's vanishing points") != std::string::npos;
  EXPECT_TRUE(said);
  ASSERT_TRUE(doc->save().ok());
  auto again = Document::open(file);
  ASSERT_TRUE(again.ok()) << again.message();
  EXPECT_EQ(again->shot().cornersPx, doc->shot().cornersPx);
}

TEST(Document, UnreadableFilesAreErrorsNamingTheFile) {
  const fs::path notAPhoto = outputDir() / "not_a_photo.png";
  std::ofstream(notAPhoto) << "this is text";
  auto photo = Document::open(notAPhoto);
  ASSERT_FALSE(photo.ok());
  EXPECT_NE(photo.message().find("not_a_photo.png"), std::string::npos) << photo.message();
  EXPECT_NE(photo.message().find("not a readable"), std::string::npos) << photo.message();

  const fs::path badShot = outputDir() / "bad_shot.json";
  std::ofstream(badShot) << "{\"image\": \"x.png\", \"focal_px\": -3}";
  auto shot = Document::open(badShot);
  ASSERT_FALSE(shot.ok());
  EXPECT_NE(shot.message().find("focal_px must be positive"), std::string::npos) << shot.message();

  auto missing = Document::open(outputDir() / "missing.json");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.message().find("no such file"), std::string::npos) << missing.message();
}

TEST(Document, ShotFileOpensCleanAndSavesWhereItWasRead) {
  const groundtruth::GroundTruth truth = groundtruth::loadGroundTruth("corridor_b");
  const fs::path dir = outputDir() / "shot";
  fs::create_directories(dir);
  fs::copy_file(truth.image, dir / "corridor_b.png", fs::copy_options::overwrite_existing);
  fs::copy_file(truth.shot, dir / "corridor_b.json", fs::copy_options::overwrite_existing);
  auto doc = Document::open(dir / "corridor_b.json");
  ASSERT_TRUE(doc.ok()) << doc.message();
  EXPECT_FALSE(doc->dirty());
  EXPECT_EQ(doc->path(), dir / "corridor_b.json");
  EXPECT_EQ(doc->shot().cornersPx, truth.cornersPx);
  EXPECT_TRUE(doc->notes().empty());

  Shot moved = doc->shot();
  moved.cornersPx[metrology::P1] += glm::dvec2(2.5, -1.25);
  doc->apply(moved, "move P1");
  EXPECT_TRUE(doc->dirty());
  ASSERT_TRUE(doc->save().ok());
  EXPECT_FALSE(doc->dirty());
  auto again = Document::open(dir / "corridor_b.json");
  ASSERT_TRUE(again.ok()) << again.message();
  EXPECT_EQ(again->shot().cornersPx, moved.cornersPx);  // JSON keeps every bit of a double
  // Undoing back past the save makes it dirty again; redoing to the saved state, clean.
  doc->undo();
  EXPECT_TRUE(doc->dirty());
  doc->redo();
  EXPECT_FALSE(doc->dirty());

  // The lens's distortion is an edit like any other: unsaved, undoable (before Shot's
  // defaulted equality, a distortion typed in was forgotten on close without asking).
  Shot bent = doc->shot();
  bent.distortion = metrology::RadialDistortion{-0.05, 0.0};
  doc->apply(bent, "distortion");
  EXPECT_TRUE(doc->dirty());
  EXPECT_TRUE(doc->hasUnsavedEdits());
  doc->undo();
  EXPECT_FALSE(doc->dirty());
}

// `detect` without --camera-height writes a shot with neither a camera height nor a
// reference length, and tells a person to check it with `photowalk edit FILE`: the editor
// opens it with the height assumed, as for a photo alone, and says so (it refused the
// file before: "give camera_height_m or a reference length").
TEST(Document, AShotFileWithoutACameraHeightOpensWithTheHeightAssumed) {
  const groundtruth::GroundTruth truth = groundtruth::loadGroundTruth("corridor_b");
  const fs::path dir = outputDir() / "no_height";
  fs::create_directories(dir);
  fs::copy_file(truth.image, dir / "corridor_b.png", fs::copy_options::overwrite_existing);
  auto text = readFile(truth.shot);
  ASSERT_TRUE(text.ok()) << text.message();
  nlohmann::json shot = nlohmann::json::parse(*text);
  ASSERT_TRUE(shot.contains("camera_height_m"));
  shot.erase("camera_height_m");
  shot.erase("reference");
  ASSERT_TRUE(writeFileAtomic(dir / "corridor_b.json", shot.dump(2)).ok());
  auto doc = Document::open(dir / "corridor_b.json");
  ASSERT_TRUE(doc.ok()) << doc.message();
  EXPECT_FALSE(doc->hasUnsavedEdits());
  EXPECT_EQ(doc->shot().cornersPx, truth.cornersPx);
  ASSERT_TRUE(doc->shot().cameraHeightM.has_value());
  EXPECT_EQ(*doc->shot().cameraHeightM, kDefaultCameraHeightM);
  EXPECT_TRUE(doc->inputOrigins().cameraHeightAssumed);
  const auto noted = [&](const std::string& words) {
    const auto notes = doc->notes();
    return std::any_of(notes.begin(), notes.end(), [&](const std::string& n) { return n.find(words) != std::string::npos; });
  };
  EXPECT_TRUE(noted("camera height assumed 1.60 m"));
  Shot set = doc->shot();
  set.cameraHeightM = 1.45;
  doc->apply(set, "camera");
  EXPECT_FALSE(noted("camera height assumed"));
  EXPECT_FALSE(doc->inputOrigins().cameraHeightAssumed);
  // The file's own height is never taken for an assumption, 1.6 m or not.
  auto given = Document::open(truth.shot);
  ASSERT_TRUE(given.ok()) << given.message();
  EXPECT_FALSE(given->inputOrigins().cameraHeightAssumed);
}

TEST(Document, UndoEverythingThenRedoEverythingSavesTheSameBytes) {
  const groundtruth::GroundTruth truth = groundtruth::loadGroundTruth("corridor_c");
  auto doc = Document::open(truth.shot);
  ASSERT_TRUE(doc.ok()) << doc.message();
  const fs::path dir = outputDir();
  ASSERT_TRUE(doc->saveCopy(dir / "before.json").ok());
  // Edits of every kind: corners (several steps of the same corner too), focal length in
  // mm, principal point, camera height.
  Shot s = doc->shot();
  for (int i = 0; i < 5; ++i) {
    s.cornersPx[i] += glm::dvec2(0.1 * (i + 1), -0.3 * i);
    doc->apply(s, "move");
  }
  s.focalMm = metrology::FocalLengthMm{24.0, 36.0};
  s.focalPx = s.focalMm->pixels(s.imageWidth);
  doc->apply(s, "focal length");
  s.principalPointPx = glm::dvec2(500.25, 380.125);
  doc->apply(s, "principal point");
  s.cameraHeightM = 1.55;
  doc->apply(s, "camera height");
  doc->apply(s, "no change");  // equal shots make no step
  EXPECT_EQ(doc->history().size(), 8u);
  ASSERT_TRUE(doc->saveCopy(dir / "after.json").ok());

  int undone = 0;
  while (doc->undo()) ++undone;
  EXPECT_EQ(undone, 8);
  ASSERT_TRUE(doc->saveCopy(dir / "undone.json").ok());
  int redone = 0;
  while (doc->redo()) ++redone;
  EXPECT_EQ(redone, 8);
  ASSERT_TRUE(doc->saveCopy(dir / "redone.json").ok());

  EXPECT_EQ(bytesOf(dir / "undone.json"), bytesOf(dir / "before.json"));
  EXPECT_EQ(bytesOf(dir / "redone.json"), bytesOf(dir / "after.json"));
  EXPECT_NE(bytesOf(dir / "after.json"), bytesOf(dir / "before.json"));
  EXPECT_NE(bytesOf(dir / "after.json").find("\"focal_mm\""), std::string::npos);  // kept in mm
}

TEST(Document, ANewEditDropsTheStepsUndone) {
  History history;
  Shot a, b, c;
  b.focalPx = 1;
  c.focalPx = 2;
  history.push({a, b, "1"});
  history.push({b, c, "2"});
  ASSERT_NE(history.undo(), nullptr);
  history.push({b, a, "3"});
  EXPECT_FALSE(history.canRedo());
  EXPECT_EQ(history.size(), 2u);
  const History::Step* step = history.undo();
  ASSERT_NE(step, nullptr);
  EXPECT_EQ(step->label, "3");
}

}  // namespace
}  // namespace pw::edit
