// photowalk edit's files end to end under an X server (xvfb-run) on lavapipe: a
// process killed during an edit offers its changes back, Save As, Export, the question
// before unsaved edits are lost (close, drop), and the file browser. Replay scripts
// drive the window; the trace (--trace: "document", "files"), the files written and the
// captures are checked. Validation is on: edit exits non-zero on any message.
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <fcntl.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "base/atomic_file.h"
#include "engine/io/model_io.h"
#include "tests/edit/edit_run.h"
#include "tests/support/groundtruth.h"

extern char** environ;

namespace pw::edit::test {
namespace {
namespace fs = std::filesystem;
using pw::test::CommandRun;

constexpr int kWidth = 960, kHeight = 600;

class EditFiles : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::path(PW_BINARY_DIR) / "test-output" / "edit_files_window";
    fs::remove_all(dir_);
    fs::remove(dir_.parent_path() / "edit_files_window_recent.json");
    fs::create_directories(dir_);
    const groundtruth::GroundTruth truth = groundtruth::loadGroundTruth("corridor_b");
    fs::copy_file(truth.image, dir_ / "corridor_b.png");
    fs::copy_file(truth.shot, dir_ / "corridor_b.json");
  }
  void SetUp() override {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no X display (run under xvfb-run)";
    setenv("PW_VALIDATION", "1", 1);
    // Never the real home's list (and not in the folder the browser shows).
    setenv("PW_RECENT_FILES", (dir_.parent_path() / "edit_files_window_recent.json").c_str(), 1);
  }

  static std::string arguments(const std::string& file, const fs::path& script, const fs::path& trace) {
    return file + " --size " + std::to_string(kWidth) + "x" + std::to_string(kHeight) + " --no-vsync --replay " +
           script.string() + " --trace " + trace.string();
  }

  // Runs the editor on `file` (may be empty) with `script`; returns the trace.
  std::vector<Row> edit(const std::string& name, const std::string& file, const std::string& script,
                        std::string* output = nullptr) {
    const fs::path scriptPath = dir_ / (name + ".replay"), tracePath = dir_ / (name + ".jsonl");
    std::ofstream(scriptPath) << script;
    fs::remove(tracePath);
    const CommandRun run = photowalk("edit " + arguments(file, scriptPath, tracePath));
    EXPECT_EQ(run.exitCode, 0) << run.output;
    if (output) *output = run.output;
    return readTrace(tracePath);
  }

  // A fresh copy of corridor_b.json named `name`.json (its photo is beside it).
  static fs::path shotCopy(const std::string& name) {
    const fs::path path = dir_ / (name + ".json");
    fs::copy_file(dir_ / "corridor_b.json", path, fs::copy_options::overwrite_existing);
    std::error_code ec;
    fs::remove(dir_ / ("." + name + ".json.autosave"), ec);
    return path;
  }

  // The first rows of the editor on `shot`, untouched.
  std::vector<Row> startRows(const fs::path& shot) { return edit("start_" + shot.stem().string(), shot.string(), "1 quit\n"); }

  static fs::path dir_;
};
fs::path EditFiles::dir_;

std::string bytesOf(const fs::path& path) {
  auto text = readFile(path);
  return text ? *text : std::string("<unreadable " + path.string() + ">");
}

std::vector<glm::dvec2> cornersOf(const fs::path& shotFile) {
  const nlohmann::json shot = nlohmann::json::parse(bytesOf(shotFile), nullptr, false);
  std::vector<glm::dvec2> corners;
  if (shot.is_discarded()) return corners;
  for (int k = 1; k <= 8; ++k) {
    const auto& p = shot.at("corners_px").at("P" + std::to_string(k));
    corners.push_back({p[0], p[1]});
  }
  return corners;
}

std::string dialogOf(const Row& row) {
  const nlohmann::json& d = row.raw.at("files").at("dialog");
  return d.is_string() ? d.get<std::string>() : "";
}

// P5's handle in the first row, and a drag of it 40 px to the right from frame 5.
Script dragP5(const std::vector<Row>& first) {
  Script script;
  script.drag(5, first.at(0).toWindow(first.at(0).corners.at(4)), {40, -12});
  return script;
}


TEST_F(EditFiles, AProcessKilledDuringAnEditOffersItsChangesBackAndRecoverGivesTheSameCorners) {
  const fs::path shot = shotCopy("killed");
  const std::string before = bytesOf(shot);
  const std::vector<Row> first = startRows(shot);
  ASSERT_FALSE(first.empty());
  ASSERT_EQ(first[0].corners.size(), 8u);

  // Edit, then wait (the replay's last event is far away) until the autosave is there;
  // then kill -9, as a crash would end it. The autosave comes after about 180 frames
  // (Autosave::kIntervalS of simulated time); the quit at 6000 leaves the test seconds
  // to see it even at 2 ms a frame, and ends the editor within minutes where the test
  // itself is killed first (a ctest run stopped: at 1000000 frames the editor ran on
  // for hours, slowing every test after it).
  Script script = dragP5(first);
  script.at(6000, "quit");
  const fs::path scriptPath = dir_ / "killed.replay", log = dir_ / "killed.log";
  std::ofstream(scriptPath) << script.str();
  const fs::path side = dir_ / ".killed.json.autosave";
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  const std::string program = PW_PHOTOWALK, sizeArg = std::to_string(kWidth) + "x" + std::to_string(kHeight);
  std::vector<std::string> args = {program,    "edit", shot.string(), "--size", sizeArg, "--no-vsync",
                                   "--replay", scriptPath.string()};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!fs::exists(side) && std::chrono::steady_clock::now() < deadline) {
    int status = 0;
    if (waitpid(pid, &status, WNOHANG) == pid) FAIL() << "the editor ended before it autosaved: " << bytesOf(log);
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ASSERT_EQ(kill(pid, SIGKILL), 0);
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
  ASSERT_TRUE(fs::exists(side)) << "no autosave within 120 s: " << bytesOf(log);
  EXPECT_EQ(bytesOf(shot), before);  // nothing saved: only the side file
  // The side file holds the drag: P5 moved by (40, -12) window pixels at the canvas's
  // scale, the other corners as they were.
  const std::vector<glm::dvec2> edited = cornersOf(side);
  ASSERT_EQ(edited.size(), 8u);
  const glm::dvec2 expected = first[0].corners[4] + glm::dvec2(40, -12) / first[0].scale;
  EXPECT_NEAR(edited[4].x, expected.x, 0.01);
  EXPECT_NEAR(edited[4].y, expected.y, 0.01);
  for (int k = 0; k < 8; ++k) {
    if (k != 4) {
      EXPECT_EQ(edited[k], first[0].corners[k]) << "P" << k + 1;
    }
  }

  // The next start offers them back; R recovers them: the same corners, unsaved, undoable.
  const std::vector<Row> next = edit("killed_next", shot.string(),
                                     Script().at(20, "capture recover.png").key(30, "R").ctrlKey(50, "Z").at(60, "quit").str());
  ASSERT_GE(next.size(), 60u);
  EXPECT_EQ(dialogOf(next[5]), "recover");
  EXPECT_EQ(next[5].corners, first[0].corners);  // the file's, until answered
  EXPECT_EQ(dialogOf(next[31]), "");
  EXPECT_EQ(next[31].corners, edited);
  EXPECT_TRUE(next[31].dirty);
  EXPECT_EQ(next[55].corners, first[0].corners);  // one undo step
  EXPECT_EQ(bytesOf(shot), before);
}

TEST_F(EditFiles, DiscardingTheRecoveredChangesRemovesTheSideFile) {
  const fs::path shot = shotCopy("discarded");
  const std::vector<Row> first = startRows(shot);
  ASSERT_FALSE(first.empty());
  std::vector<glm::dvec2> moved = first[0].corners;
  // A side file as a crash leaves it: the shot with P3 moved.
  nlohmann::json side = nlohmann::json::parse(bytesOf(shot));
  side["corners_px"]["P3"][0] = double(side["corners_px"]["P3"][0]) + 5.0;
  std::ofstream(dir_ / ".discarded.json.autosave") << side.dump();
  const std::vector<Row> rows = edit("discarded", shot.string(), Script().key(10, "D").at(20, "quit").str());
  ASSERT_GE(rows.size(), 20u);
  EXPECT_EQ(dialogOf(rows[5]), "recover");
  EXPECT_EQ(dialogOf(rows[15]), "");
  EXPECT_EQ(rows[15].corners, first[0].corners);
  EXPECT_FALSE(rows[15].dirty);
  EXPECT_FALSE(fs::exists(dir_ / ".discarded.json.autosave"));
}

TEST_F(EditFiles, NothingElseOpensWhileTheRecoveryQuestionIsUnansweredAndClosingKeepsTheSideFile) {
  const fs::path shot = shotCopy("unanswered"), other = shotCopy("unanswered_other");
  nlohmann::json side = nlohmann::json::parse(bytesOf(shot));
  side["corners_px"]["P6"][1] = double(side["corners_px"]["P6"][1]) - 4.0;
  const fs::path sidePath = dir_ / ".unanswered.json.autosave";
  std::ofstream(sidePath) << side.dump();
  std::string output;
  const std::vector<Row> rows =
      edit("unanswered", shot.string(), Script().at(10, "drop " + other.string()).at(20, "close").at(300, "quit").str(),
           &output);
  ASSERT_GE(rows.size(), 20u);
  EXPECT_EQ(fs::path(rows[15].path.value_or("")), shot);
  EXPECT_EQ(dialogOf(rows[15]), "recover");
  EXPECT_NE(output.find("first answer the question"), std::string::npos) << output;
  EXPECT_LT(rows.back().frame, 25);  // the file is clean: the window closes, asking nothing more
  EXPECT_TRUE(fs::exists(sidePath)) << "the unanswered side file is offered again next time";
}

TEST_F(EditFiles, SaveAsThenReopenGivesTheSameCorners) {
  const fs::path shot = shotCopy("save_as");
  const std::string before = bytesOf(shot);
  const std::vector<Row> first = startRows(shot);
  ASSERT_FALSE(first.empty());
  fs::create_directories(dir_ / "saved");
  fs::remove(dir_ / "saved" / "moved.json");
  // Ctrl+Shift+S shows the browser (captured: the README's picture), Esc leaves it; the
  // replay's save-as then does what its Save does.
  Script script = dragP5(first);
  script.ctrlKey(14, "S", true).at(17, "capture save_as.png").key(18, "ESCAPE").at(20, "save-as saved/moved.json").at(30, "quit");
  const std::vector<Row> rows = edit("save_as", shot.string(), script.str());
  ASSERT_GE(rows.size(), 30u);
  EXPECT_EQ(dialogOf(rows[16]), "save-as");
  EXPECT_EQ(fs::path(rows[16].raw["files"]["folder"].get<std::string>()), dir_);
  EXPECT_EQ(rows[16].raw["files"]["name"], "save_as.json");  // the file name field, filled in
  EXPECT_EQ(dialogOf(rows[19]), "");
  const std::vector<glm::dvec2> edited = rows[15].corners;
  EXPECT_TRUE(rows[15].dirty);
  ASSERT_TRUE(rows[25].path.has_value());
  EXPECT_EQ(fs::path(*rows[25].path), dir_ / "saved" / "moved.json");
  EXPECT_FALSE(rows[25].dirty);
  EXPECT_EQ(bytesOf(shot), before);
  EXPECT_FALSE(fs::exists(dir_ / ".save_as.json.autosave"));

  const std::vector<Row> reopened = edit("save_as_reopen", (dir_ / "saved" / "moved.json").string(), "2 quit\n");
  ASSERT_FALSE(reopened.empty());
  EXPECT_EQ(reopened[0].corners, edited);
  EXPECT_FALSE(reopened[0].dirty);
  // The recent files list (PW_RECENT_FILES) has it first.
  const nlohmann::json recent = reopened[0].raw.at("files").at("recent");
  ASSERT_FALSE(recent.empty());
  EXPECT_EQ(fs::path(recent[0].get<std::string>()), dir_ / "saved" / "moved.json");
}

TEST_F(EditFiles, ExportWritesVrmlGltfAndAWebPageAndAFailureIsAMessage) {
  const fs::path shot = shotCopy("exported");
  for (const char* name : {"exported.wrl", "exported.glb", "exported.html"}) fs::remove(dir_ / name);
  std::string output;
  edit("export", shot.string(),
       Script().at(5, "export exported.wrl").at(6, "export exported.glb").at(7, "export missing/x.glb")
           .at(8, "export exported.html").at(10, "quit").str(),
       &output);
  EXPECT_NE(output.find("error: not exported: "), std::string::npos) << output;
  EXPECT_FALSE(fs::exists(dir_ / "missing"));
  for (const char* name : {"exported.wrl", "exported.glb"}) {
    std::vector<std::string> warnings;
    auto scene = engine::loadModel(dir_ / name, &warnings);
    ASSERT_TRUE(scene.ok()) << name << ": " << scene.message();
    EXPECT_GE(scene->shapes.size(), 5u) << name;
    EXPECT_TRUE(std::any_of(scene->viewpoints.begin(), scene->viewpoints.end(),
                            [](const engine::Viewpoint& v) { return v.description == "Photo"; }))
        << name;
  }
  // The convert command reads them too.
  const CommandRun convert = photowalk("convert " + (dir_ / "exported.glb").string() + " " + (dir_ / "back.wrl").string());
  EXPECT_EQ(convert.exitCode, 0) << convert.output;
  // The web page (tests/web opens such pages in a browser): the model, the viewer, and
  // the Photo viewpoint with its lens in what the page knows. (A photowalk built
  // without the viewer says so instead of writing the page.)
  if (!fs::exists(dir_ / "exported.html") && output.find("built without the web page's viewer") != std::string::npos) {
    GTEST_SKIP() << "photowalk was built without the web page's viewer (scripts/install-tools.sh)";
  }
  const std::string page = bytesOf(dir_ / "exported.html");
  EXPECT_NE(page.find("<script type=\"application/octet-stream\" id=\"pw-model\">Z2xURg"), std::string::npos)
      << "a base64 binary glTF ('glTF')";
  const std::string metaTag = "id=\"pw-meta\">";
  const size_t meta = page.find(metaTag);
  ASSERT_NE(meta, std::string::npos);
  const size_t start = meta + metaTag.size();
  const auto info = nlohmann::json::parse(page.substr(start, page.find("</script>", start) - start));
  EXPECT_EQ(info["viewpoints"][0]["description"], "Photo");
  EXPECT_TRUE(info["viewpoints"][0].contains("intrinsics"));
  EXPECT_EQ(info["dimensions"].size(), 1u);
}

TEST_F(EditFiles, ThePanelsExportButtonOffersTheModelsNameAndEnterWritesIt) {
  // A photo opened alone: its shot would be corridor_b.shot.json; the model corridor_b.wrl.
  fs::remove(dir_ / "corridor_b.wrl");
  // (The panel settles in its second frame: its wrapped notes are measured in the first.)
  const std::vector<Row> first = edit("export_button_ask", (dir_ / "corridor_b.png").string(), "6 quit\n");
  ASSERT_GE(first.size(), 6u);
  const nlohmann::json button = first[5].raw["files"]["buttons"]["Export .wrl"];
  ASSERT_EQ(button.size(), 4u) << first[5].raw["files"].dump();
  const std::vector<Row> rows = edit("export_button", (dir_ / "corridor_b.png").string(),
                                     Script().click(3, button).key(10, "ENTER").at(14, "quit").str());
  ASSERT_GE(rows.size(), 14u);
  EXPECT_EQ(dialogOf(rows[8]), "export");
  EXPECT_EQ(rows[8].raw["files"]["name"], "corridor_b.wrl");
  EXPECT_EQ(dialogOf(rows[12]), "");
  std::vector<std::string> warnings;
  auto scene = engine::loadModel(dir_ / "corridor_b.wrl", &warnings);
  ASSERT_TRUE(scene.ok()) << scene.message();
  EXPECT_GE(scene->shapes.size(), 5u);
}

TEST_F(EditFiles, ClosingWithUnsavedChangesAsksAndKeepsTheWindowUntilAnswered) {
  const fs::path shot = shotCopy("closing");
  const std::string before = bytesOf(shot);
  const std::vector<Row> first = startRows(shot);
  ASSERT_FALSE(first.empty());
  Script script = dragP5(first);
  script.at(20, "close").at(30, "capture unsaved.png").key(40, "ESCAPE").at(50, "close").key(70, "D").at(300, "quit");
  const std::vector<Row> rows = edit("closing", shot.string(), script.str());
  ASSERT_GE(rows.size(), 70u);
  EXPECT_EQ(dialogOf(rows[19]), "");
  EXPECT_EQ(dialogOf(rows[25]), "unsaved");
  EXPECT_TRUE(rows[39].raw["files"]["buttons"].contains("Save"));
  EXPECT_EQ(dialogOf(rows[45]), "");  // Esc: Cancel; the window stays, the edit too
  EXPECT_TRUE(rows[45].dirty);
  EXPECT_EQ(dialogOf(rows[60]), "unsaved");
  EXPECT_LT(rows.back().frame, 80) << "Discard closes the window at once";
  EXPECT_EQ(bytesOf(shot), before);
  EXPECT_FALSE(fs::exists(dir_ / ".closing.json.autosave"));  // a clean close after Discard
  EXPECT_TRUE(fs::exists(dir_ / "unsaved.png"));
}

TEST_F(EditFiles, ClickingSaveInTheQuestionSavesAndCloses) {
  const fs::path shot = shotCopy("close_save");
  const std::vector<Row> first = startRows(shot);
  ASSERT_FALSE(first.empty());
  // Where the dialog's Save button is, from a run that only asks.
  Script ask = dragP5(first);
  ask.at(20, "close").at(30, "quit");
  const std::vector<Row> asked = edit("close_save_ask", shot.string(), ask.str());
  ASSERT_GE(asked.size(), 30u);
  const nlohmann::json saveButton = asked[28].raw["files"]["buttons"]["Save"];
  ASSERT_EQ(saveButton.size(), 4u);
  const std::vector<glm::dvec2> edited = asked[15].corners;

  const fs::path again = shotCopy("close_save");
  Script script = dragP5(first);
  script.at(20, "close").click(30, saveButton).at(300, "quit");
  const std::vector<Row> rows = edit("close_save", again.string(), script.str());
  ASSERT_FALSE(rows.empty());
  EXPECT_LT(rows.back().frame, 40);
  EXPECT_EQ(cornersOf(again), edited);
  EXPECT_FALSE(fs::exists(dir_ / ".close_save.json.autosave"));
}

TEST_F(EditFiles, AClosedWindowWithoutChangesClosesAtOnce) {
  const fs::path shot = shotCopy("clean_close");
  const std::vector<Row> rows = edit("clean_close", shot.string(), Script().at(5, "close").at(300, "quit").str());
  ASSERT_FALSE(rows.empty());
  EXPECT_LT(rows.back().frame, 8);
}

TEST_F(EditFiles, DroppingAnotherFileWithUnsavedChangesAsksFirst) {
  const fs::path shot = shotCopy("dropping"), other = shotCopy("dropped");
  const std::vector<Row> first = startRows(shot);
  ASSERT_FALSE(first.empty());
  Script script = dragP5(first);
  script.at(20, "drop " + other.string()).key(30, "ESCAPE").at(40, "drop " + other.string()).key(50, "D").at(60, "quit");
  const std::vector<Row> rows = edit("dropping", shot.string(), script.str());
  ASSERT_GE(rows.size(), 60u);
  EXPECT_EQ(dialogOf(rows[25]), "unsaved");
  EXPECT_EQ(fs::path(rows[35].path.value_or("")), shot);  // Cancel: still the first file, edited
  EXPECT_TRUE(rows[35].dirty);
  EXPECT_EQ(dialogOf(rows[45]), "unsaved");
  EXPECT_EQ(fs::path(rows[55].path.value_or("")), other);  // Discard: the other file
  EXPECT_FALSE(rows[55].dirty);
}

TEST_F(EditFiles, TheEmptyWindowOffersTheRecentFilesAndOpensOneClicked) {
  const fs::path recentList = dir_ / "recent_empty" / "recent.json";  // made by the first open
  fs::remove_all(recentList.parent_path());
  setenv("PW_RECENT_FILES", recentList.c_str(), 1);
  const fs::path shot = shotCopy("recent_one");
  edit("recent_open", shot.string(), "1 quit\n");
  ASSERT_TRUE(fs::exists(recentList));
  const std::vector<Row> empty = edit("recent_empty", "", "2 capture recent_empty.png\n3 quit\n");
  ASSERT_GE(empty.size(), 3u);
  EXPECT_TRUE(empty[2].corners.empty());
  const nlohmann::json buttons = empty[2].raw["files"]["buttons"];
  ASSERT_TRUE(buttons.contains("recent:" + shot.string())) << buttons.dump();
  ASSERT_TRUE(buttons.contains("Open"));
  const std::vector<Row> rows =
      edit("recent_click", "", Script().click(3, buttons["recent:" + shot.string()]).at(10, "quit").str());
  ASSERT_GE(rows.size(), 10u);
  EXPECT_EQ(fs::path(rows[8].path.value_or("")), shot);
  EXPECT_EQ(rows[8].corners.size(), 8u);
}

TEST_F(EditFiles, TheBrowserListsAndFiltersAFolderAndOpensWhatIsClicked) {
  const fs::path folder = dir_ / "browse";
  fs::remove_all(folder);
  fs::create_directories(folder / "more");
  fs::copy_file(dir_ / "corridor_b.png", folder / "corridor_b.png");
  fs::copy_file(dir_ / "corridor_b.json", folder / "hall.json");
  std::ofstream(folder / "notes.txt") << "not shown";
  std::ofstream(folder / ".hall.json.autosave") << "hidden";
  // Opened empty (no file) with no recent files: Ctrl+O shows the browser in the current folder.
  fs::remove(dir_ / "browse_recent.json");
  setenv("PW_RECENT_FILES", (dir_ / "browse_recent.json").c_str(), 1);
  const fs::path scriptPath = dir_ / "browse.replay", tracePath = dir_ / "browse.jsonl";
  std::ofstream(scriptPath) << Script().at(2, "capture empty.png").ctrlKey(5, "O").at(10, "capture browser.png").at(12, "quit").str();
  // Run from the folder itself, so that the browser starts there.
  const CommandRun inFolder =
      pw::test::runCommand("cd " + folder.string() + " && " + PW_PHOTOWALK + " edit " + arguments("", scriptPath, tracePath));
  ASSERT_EQ(inFolder.exitCode, 0) << inFolder.output;
  const std::vector<Row> rows = readTrace(tracePath);
  ASSERT_GE(rows.size(), 12u);
  EXPECT_TRUE(rows[3].corners.empty());
  const nlohmann::json files = rows[11].raw.at("files");
  EXPECT_EQ(files.at("dialog"), "open");
  EXPECT_EQ(fs::canonical(files.at("folder").get<std::string>()), fs::canonical(folder));
  EXPECT_EQ(files.at("entries"), nlohmann::json::array({"more/", "corridor_b.png", "hall.json"}));
  ASSERT_TRUE(files.at("buttons").contains("entry:hall.json"));
  ASSERT_TRUE(files.at("buttons").contains("Confirm"));

  // Click hall.json, then Open.
  std::ofstream(scriptPath) << Script()
                                   .ctrlKey(5, "O")
                                   .click(10, files["buttons"]["entry:hall.json"])
                                   .click(15, files["buttons"]["Confirm"])
                                   .at(25, "quit")
                                   .str();
  const CommandRun opened =
      pw::test::runCommand("cd " + folder.string() + " && " + PW_PHOTOWALK + " edit " + arguments("", scriptPath, tracePath));
  ASSERT_EQ(opened.exitCode, 0) << opened.output;
  const std::vector<Row> after = readTrace(tracePath);
  ASSERT_GE(after.size(), 25u);
  ASSERT_TRUE(after[22].path.has_value());
  EXPECT_EQ(fs::canonical(*after[22].path), fs::canonical(folder / "hall.json"));
  EXPECT_EQ(after[22].corners.size(), 8u);
  EXPECT_EQ(dialogOf(after[22]), "");
}

}  // namespace
}  // namespace pw::edit::test
