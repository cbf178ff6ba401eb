// The editor's files without a window: the browser's listing and filter, the recent
// files list, Save As, autosave and recovery, and Export with the build's code.
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "base/atomic_file.h"
#include "editor/edit/autosave.h"
#include "editor/edit/document.h"
#include "editor/edit/file_browser.h"
#include "editor/edit/model_export.h"
#include "engine/io/model_io.h"
#include "metrology/measure.h"
#include "modeling/shot_file.h"
#include "tests/support/groundtruth.h"

namespace pw::edit {
namespace {
namespace fs = std::filesystem;
using metrology::Shot;

fs::path freshDir(const std::string& name) {
  const fs::path dir = fs::path(PW_BINARY_DIR) / "test-output" / "edit_files" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void touch(const fs::path& path) { std::ofstream(path) << "x"; }

std::vector<std::string> namesOf(const std::vector<FolderEntry>& entries) {
  std::vector<std::string> names;
  for (const FolderEntry& e : entries) names.push_back(e.name + (e.folder ? "/" : ""));
  return names;
}

// corridor_b's photo and shot file, copied into `dir`; returns the shot's path.
fs::path corridorIn(const fs::path& dir) {
  const groundtruth::GroundTruth truth = groundtruth::loadGroundTruth("corridor_b");
  fs::copy_file(truth.image, dir / "corridor_b.png", fs::copy_options::overwrite_existing);
  fs::copy_file(truth.shot, dir / "corridor_b.json", fs::copy_options::overwrite_existing);
  return dir / "corridor_b.json";
}

std::string bytesOf(const fs::path& path) {
  auto text = readFile(path);
  return text ? *text : std::string("<unreadable>");
}

TEST(FileBrowser, ListsFoldersFirstThenPhotosAndShotsInNameOrder) {
  const fs::path dir = freshDir("list");
  for (const char* name : {"b.jpg", "A.PNG", "c.jpeg", "B.json", "notes.txt", "model.wrl", ".hidden.json",
                           ".corridor.json.autosave", "photo.png.bak"}) {
    touch(dir / name);
  }
  fs::create_directory(dir / "zeta");
  fs::create_directory(dir / "Alpha");
  fs::create_directory(dir / ".git");
  auto listed = listFolder(dir, kOpenableEndings);
  ASSERT_TRUE(listed.ok()) << listed.message();
  EXPECT_EQ(namesOf(*listed), (std::vector<std::string>{"Alpha/", "zeta/", "A.PNG", "b.jpg", "B.json", "c.jpeg"}));
  EXPECT_TRUE((*listed)[0].folder);
  EXPECT_EQ((*listed)[2].path, dir / "A.PNG");

  auto models = listFolder(dir, kModelEndings);
  ASSERT_TRUE(models.ok());
  EXPECT_EQ(namesOf(*models), (std::vector<std::string>{"Alpha/", "zeta/", "model.wrl"}));
  auto everything = listFolder(dir, {});
  ASSERT_TRUE(everything.ok());
  EXPECT_EQ(everything->size(), 9u);  // 2 folders, 7 files not hidden
}

TEST(FileBrowser, EntersFoldersAndGoesUpAndStaysWhereItWasOnAnError) {
  const fs::path dir = freshDir("enter");
  fs::create_directory(dir / "inner");
  touch(dir / "inner" / "shot.json");
  FileBrowser browser(kShotEndings);
  ASSERT_TRUE(browser.enter(dir / "inner").ok());
  EXPECT_EQ(browser.folder(), dir / "inner");
  EXPECT_EQ(namesOf(browser.entries()), (std::vector<std::string>{"shot.json"}));
  ASSERT_TRUE(browser.up().ok());
  EXPECT_EQ(browser.folder(), dir);
  EXPECT_EQ(namesOf(browser.entries()), (std::vector<std::string>{"inner/"}));
  const Status missing = browser.enter(dir / "missing");
  EXPECT_FALSE(missing.ok());
  EXPECT_NE(missing.message().find("not a folder"), std::string::npos) << missing.message();
  EXPECT_EQ(browser.folder(), dir);
  EXPECT_FALSE(listFolder(dir / "inner" / "shot.json", {}).ok());  // a file is not a folder
}

TEST(RecentFiles, KeepsTheNewestTenFirstAndReadsThemBack) {
  const fs::path dir = freshDir("recent");
  const fs::path list = dir / "config" / "photowalk" / "recent.json";  // folders made on the first write
  RecentFiles recent = RecentFiles::load(list);
  EXPECT_TRUE(recent.paths().empty());
  EXPECT_TRUE(recent.problem().empty());
  for (int i = 0; i < 12; ++i) ASSERT_TRUE(recent.add(dir / ("shot" + std::to_string(i) + ".json")).ok());
  ASSERT_TRUE(recent.add(dir / "sub" / ".." / "shot5.json").ok());  // again: moves to the front, once
  ASSERT_EQ(recent.paths().size(), RecentFiles::kMaxFiles);
  EXPECT_EQ(recent.paths()[0], dir / "shot5.json");
  EXPECT_EQ(recent.paths()[1], dir / "shot11.json");
  EXPECT_EQ(std::count(recent.paths().begin(), recent.paths().end(), dir / "shot5.json"), 1);
  EXPECT_EQ(recent.paths().back(), dir / "shot2.json");  // shot0 and shot1 fell off

  const RecentFiles again = RecentFiles::load(list);
  EXPECT_EQ(again.paths(), recent.paths());
  EXPECT_EQ(std::distance(fs::directory_iterator(list.parent_path()), fs::directory_iterator()), 1)
      << "only recent.json: the atomic write leaves no temporary";
  ASSERT_TRUE(recent.remove(dir / "shot5.json").ok());
  EXPECT_EQ(RecentFiles::load(list).paths().front(), dir / "shot11.json");
}

TEST(RecentFiles, AMalformedListIsEmptyWithAReasonAndReplacedOnTheNextAdd) {
  const fs::path dir = freshDir("recent_bad");
  std::ofstream(dir / "recent.json") << "{\"recent\": 3";
  RecentFiles recent = RecentFiles::load(dir / "recent.json");
  EXPECT_TRUE(recent.paths().empty());
  EXPECT_NE(recent.problem().find("not a recent files list"), std::string::npos) << recent.problem();
  ASSERT_TRUE(recent.add(dir / "a.json").ok());
  EXPECT_EQ(RecentFiles::load(dir / "recent.json").paths().size(), 1u);
}

TEST(RecentFiles, LivesWhereTheEnvironmentSays) {
  const char* saved = std::getenv("PW_RECENT_FILES");
  const std::string before = saved ? saved : "";
  setenv("PW_RECENT_FILES", "/tmp/pw-recent-test.json", 1);
  EXPECT_EQ(defaultRecentFilesPath(), fs::path("/tmp/pw-recent-test.json"));
  unsetenv("PW_RECENT_FILES");
  setenv("XDG_CONFIG_HOME", "/tmp/pw-config", 1);
  EXPECT_EQ(defaultRecentFilesPath(), fs::path("/tmp/pw-config/photowalk/recent.json"));
  unsetenv("XDG_CONFIG_HOME");
  setenv("HOME", "/tmp/pw-home", 1);
  EXPECT_EQ(defaultRecentFilesPath(), fs::path("/tmp/pw-home/.config/photowalk/recent.json"));
  if (saved) setenv("PW_RECENT_FILES", before.c_str(), 1);
}

TEST(SaveAs, WritesTheShotElsewhereKeepingUnknownFieldsAndTheDocumentMovesThere) {
  const fs::path dir = freshDir("save_as");
  const fs::path original = corridorIn(dir);
  const std::string originalBytes = bytesOf(original);
  auto doc = Document::open(original);
  ASSERT_TRUE(doc.ok()) << doc.message();
  Shot moved = doc->shot();
  moved.cornersPx[metrology::P5] += glm::dvec2(3.25, -1.5);
  doc->apply(moved, "move P5");
  fs::create_directory(dir / "elsewhere");
  const fs::path target = dir / "elsewhere" / "moved.json";
  ASSERT_TRUE(doc->saveAs(target).ok());
  EXPECT_EQ(doc->path(), target);
  EXPECT_FALSE(doc->dirty());
  EXPECT_FALSE(doc->hasUnsavedEdits());
  EXPECT_EQ(bytesOf(original), originalBytes);  // the file it came from is as it was

  auto reopened = Document::open(target);  // its photo found from the other folder
  ASSERT_TRUE(reopened.ok()) << reopened.message();
  EXPECT_EQ(reopened->shot().cornersPx, moved.cornersPx);
  EXPECT_EQ(reopened->photo().cols, doc->photo().cols);
  const nlohmann::json written = nlohmann::json::parse(bytesOf(target));
  const nlohmann::json given = nlohmann::json::parse(originalBytes);
  for (const auto& [key, value] : given.items()) {
    if (key == "image" || key == "corners_px") continue;
    EXPECT_EQ(written.at(key), value) << key;  // ground-truth extras and units kept
  }
  EXPECT_EQ(written.at("image"), "../corridor_b.png");
  EXPECT_FALSE(doc->saveAs(dir / "missing" / "x.json").ok());
  EXPECT_EQ(doc->path(), target);  // a failed Save As leaves the document where it was
}

TEST(Autosave, WritesTheSideFileEveryFewSecondsOfUnsavedEditsAndRemovesItOnceSaved) {
  const fs::path dir = freshDir("autosave");
  const fs::path shotPath = corridorIn(dir);
  auto doc = Document::open(shotPath);
  ASSERT_TRUE(doc.ok()) << doc.message();
  const fs::path side = autosavePath(shotPath);
  EXPECT_EQ(side, dir / ".corridor_b.json.autosave");
  Autosave autosave;
  const double step = 1.0 / 60;
  const int interval = int(Autosave::kIntervalS / step + 0.5);
  for (int i = 0; i < 2 * interval; ++i) ASSERT_TRUE(autosave.step(&*doc, step).ok());
  EXPECT_FALSE(fs::exists(side)) << "nothing to keep while there are no edits";

  Shot moved = doc->shot();
  moved.cornersPx[metrology::P2] += glm::dvec2(-7.125, 2.5);
  doc->apply(moved, "move P2");
  for (int i = 0; i < interval + 1; ++i) ASSERT_TRUE(autosave.step(&*doc, step).ok());
  ASSERT_TRUE(fs::exists(side));
  auto kept = modeling::readShotFile(side);
  ASSERT_TRUE(kept.ok()) << kept.message();
  EXPECT_EQ(kept->cornersPx, moved.cornersPx);  // exactly: shortest round-trip decimals

  // What a crash leaves is offered on the next open, as the state with the edit.
  auto next = Document::open(shotPath);
  ASSERT_TRUE(next.ok());
  auto recovered = recoverableShot(*next);
  ASSERT_TRUE(recovered.ok()) << recovered.message();
  ASSERT_TRUE(recovered->has_value());
  EXPECT_TRUE(**recovered == doc->shot());

  ASSERT_TRUE(doc->save().ok());
  autosave.remove(doc->path());
  EXPECT_FALSE(fs::exists(side));
  auto clean = Document::open(shotPath);
  ASSERT_TRUE(clean.ok());
  auto none = recoverableShot(*clean);
  ASSERT_TRUE(none.ok());
  EXPECT_FALSE(none->has_value());
}

TEST(Autosave, RemovesItsSideFileWhenTheEditsAreUndone) {
  const fs::path dir = freshDir("autosave_undo");
  const fs::path shotPath = corridorIn(dir);
  auto doc = Document::open(shotPath);
  ASSERT_TRUE(doc.ok());
  Shot moved = doc->shot();
  moved.focalPx *= 1.01;
  doc->apply(moved, "focal length");
  Autosave autosave;
  ASSERT_TRUE(autosave.step(&*doc, Autosave::kIntervalS).ok());
  ASSERT_TRUE(fs::exists(autosavePath(shotPath)));
  doc->undo();
  ASSERT_TRUE(autosave.step(&*doc, Autosave::kIntervalS).ok());
  EXPECT_FALSE(fs::exists(autosavePath(shotPath)));
}

TEST(Autosave, APhotoNeverSavedHasUnsavedEditsOnlyOnceEdited) {
  const groundtruth::GroundTruth truth = groundtruth::loadGroundTruth("corridor_b");
  auto doc = Document::open(truth.image);
  ASSERT_TRUE(doc.ok());
  EXPECT_TRUE(doc->dirty());
  EXPECT_FALSE(doc->hasUnsavedEdits());  // opening it again detects the same corners
  Shot moved = doc->shot();
  moved.cornersPx[metrology::P1].x += 1;
  doc->apply(moved, "move P1");
  EXPECT_TRUE(doc->hasUnsavedEdits());
  doc->undo();
  EXPECT_FALSE(doc->hasUnsavedEdits());
}

TEST(Autosave, ASideFileThatCannotBeReadIsAnErrorAndStays) {
  const fs::path dir = freshDir("autosave_bad");
  const fs::path shotPath = corridorIn(dir);
  {
    std::ofstream side(autosavePath(shotPath));
    side << "{ not json";
    ASSERT_TRUE(side.flush()) << "could not write " << autosavePath(shotPath);
  }
  // (This test failed once in a loaded CI run, cause not found: each step says what it saw.)
  ASSERT_EQ(bytesOf(autosavePath(shotPath)), "{ not json");
  auto doc = Document::open(shotPath);
  ASSERT_TRUE(doc.ok()) << doc.message();
  auto recovered = recoverableShot(*doc);
  ASSERT_FALSE(recovered.ok()) << "recovered " << (recovered.ok() && recovered->has_value() ? "a shot" : "nothing")
                               << " from " << autosavePath(shotPath) << ", which holds: " << bytesOf(autosavePath(shotPath));
  EXPECT_NE(recovered.message().find("cannot be read"), std::string::npos) << recovered.message();
  EXPECT_TRUE(fs::exists(autosavePath(shotPath)));
}

TEST(ModelExport, WritesVrmlAndGltfThatPhotowalkReadsBack) {
  const fs::path dir = freshDir("export");
  auto doc = Document::open(corridorIn(dir));
  ASSERT_TRUE(doc.ok());
  auto measurement = metrology::measureCorridor(doc->shot());
  ASSERT_TRUE(measurement.ok()) << measurement.message();
  for (const char* name : {"model.wrl", "model.glb"}) {
    const fs::path out = dir / name;
    ASSERT_TRUE(exportModel(doc->shot(), doc->photo(), *measurement, out).ok()) << name;
    std::vector<std::string> warnings;
    auto scene = engine::loadModel(out, &warnings);
    ASSERT_TRUE(scene.ok()) << name << ": " << scene.message();
    EXPECT_GE(scene->shapes.size(), 5u) << name;  // far wall, walls, floor, ceiling
    EXPECT_TRUE(std::any_of(scene->viewpoints.begin(), scene->viewpoints.end(),
                            [](const engine::Viewpoint& v) { return v.description == "Photo"; }))
        << name;
    EXPECT_FALSE(scene->tour.empty()) << name << ": the build's tour";
  }
  const Status wrongName = exportModel(doc->shot(), doc->photo(), *measurement, dir / "model.obj");
  EXPECT_FALSE(wrongName.ok());
  EXPECT_NE(wrongName.message().find(".wrl"), std::string::npos) << wrongName.message();
  EXPECT_FALSE(exportModel(doc->shot(), doc->photo(), *measurement, dir / "missing" / "model.glb").ok());
  EXPECT_FALSE(fs::exists(dir / "missing"));
}

}  // namespace
}  // namespace pw::edit
