// The app shell with two modes switched at run time, under an X server (xvfb-run) on
// lavapipe with validation on: the walkthrough and a test-only mode. The walk keeps
// where it stood while the other mode runs; the other gets the input meanwhile; a
// capture in the other mode is the window as shown, ImGui included.
#include "editor/app/shell.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "editor/walk/replay.h"
#include "editor/walk/walk_mode.h"
#include "engine/scene/image.h"
#include "engine/scene/sample_scene.h"

namespace pw::app {
namespace {
namespace fs = std::filesystem;

const glm::vec3 kMagenta(1.0f, 0.0f, 1.0f);

// A second mode, as the editor will be: it draws no scene (a magenta clear) and an ImGui
// window at (20, 20), and counts what the shell gives it.
class OtherMode : public AppMode {
 public:
  std::string_view name() const override { return "other"; }
  void onEnter(Shell&) override { ++enters; }
  void onLeave(Shell&) override { ++leaves; }
  void onInput(Shell&, const InputEvent& event) override {
    if (const auto* key = std::get_if<KeyEvent>(&event)) keys.push_back(*key);
  }
  void update(Shell&, double stepS) override { simulatedS += stepS; }
  void traceRow(TraceRow& row) const override { row.add("simulated_s", simulatedS); }
  void drawUi(Shell&) override {
    ImGui::SetNextWindowPos({20, 20}, ImGuiCond_Always);
    ImGui::SetNextWindowSize({200, 100}, ImGuiCond_Always);
    ImGui::Begin("other mode", nullptr, ImGuiWindowFlags_NoSavedSettings);
    ImGui::TextUnformatted("not the walk");
    ImGui::End();
  }
  FrameContent frame(Shell&) override { return {{}, kMagenta}; }
  // Objects to the first `refuseCloses` close requests (as the editor with unsaved edits).
  bool onCloseRequest(Shell&) override { return ++closeAsks > refuseCloses; }

  int enters = 0, leaves = 0;
  int closeAsks = 0, refuseCloses = 0;
  std::vector<KeyEvent> keys;
  double simulatedS = 0;
};

class ShellTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no X display (ctest runs this test under xvfb-run)";
    dir_ = fs::path(PW_BINARY_DIR) / "test-output" / "app_shell";
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }

  ShellOptions options(const std::string& script) {
    auto replay = walk::parseReplay(script, "test.replay", dir_);
    EXPECT_TRUE(replay.ok()) << replay.message();
    ShellOptions o;
    o.window = {320, 180, "photowalk shell test"};
    o.vsync = false;
    o.renderer.forceCpu = true;
    o.renderer.validation = engine::RendererOptions::Validation::kOn;
    o.renderer.profile = engine::RenderProfile::kInteractive;
    if (replay.ok()) o.replay = *replay;
    o.tracePath = dir_ / "trace.jsonl";
    return o;
  }

  std::vector<nlohmann::json> trace() const {
    std::vector<nlohmann::json> rows;
    std::ifstream in(dir_ / "trace.jsonl");
    for (std::string line; std::getline(in, line);) rows.push_back(nlohmann::json::parse(line));
    return rows;
  }

  engine::Image load(const std::string& name) const {
    auto image = engine::loadImage(dir_ / name);
    EXPECT_TRUE(image.ok()) << image.message();
    return image.ok() ? *image : engine::Image{};
  }

  fs::path dir_;
};

TEST_F(ShellTest, WalkKeepsItsPlaceWhileAnotherModeRuns) {
  const engine::Scene scene = engine::makeSampleScene();
  auto shell = Shell::create(options(
      "0 key W down\n"
      "29 capture walk_before.png\n"
      "30 mode other\n"  // W still held: the walk lets go of it when it is left
      "35 key W up\n36 key W down\n60 key W up\n"
      "62 capture other.png\n"
      "70 mode walk\n"
      "72 capture walk_after.png\n"
      "80 quit\n"));
  ASSERT_TRUE(shell.ok()) << shell.message();
  walk::WalkMode walkMode(scene, {});
  OtherMode other;
  ASSERT_TRUE((*shell)->addMode(walkMode).ok());
  ASSERT_TRUE((*shell)->addMode(other).ok());
  EXPECT_FALSE((*shell)->addMode(other).ok());  // one mode per name
  auto report = (*shell)->run("walk");
  ASSERT_TRUE(report.ok()) << report.message();  // with validation on: no message either
  EXPECT_EQ(report->framesSimulated, 81);
  EXPECT_EQ(report->validationMessages, 0u);

  // The trace says which mode ran each frame.
  const auto rows = trace();
  ASSERT_EQ(rows.size(), 81u);
  for (int f = 0; f <= 80; ++f) {
    EXPECT_EQ(rows[f]["frame"], f);
    EXPECT_EQ(rows[f]["mode"], f >= 30 && f < 70 ? "other" : "walk") << "frame " << f;
  }
  // The walk moved while W was down (at the sample room's speed, 1 m/s, towards -z)
  // and, back from the other mode, stands exactly where it was left.
  ASSERT_EQ(scene.navigation.speedMps, 1.0f);
  EXPECT_NEAR(rows[29]["z"].get<double>() - rows[0]["z"].get<double>(), -29.0 / 60, 1e-4);
  // (Standing, the avatar's eye height alternates by a float's last bit from step to
  // step as gravity and the floor meet: 1.5999999 and 1.6000000 m, measured.)
  for (int f = 70; f <= 80; ++f) {
    for (const char* field : {"x", "z", "yaw_deg", "pitch_deg"}) {
      EXPECT_EQ(rows[f][field], rows[29][field]) << field << " at frame " << f;
    }
    EXPECT_NEAR(rows[f]["y"].get<double>(), rows[29]["y"].get<double>(), 1e-6) << "frame " << f;
  }
  // The other mode got the keys of its time, and only those, and its steps.
  EXPECT_EQ(other.enters, 1);
  EXPECT_EQ(other.leaves, 1);
  ASSERT_EQ(other.keys.size(), 3u);
  EXPECT_EQ(other.keys[0].key, GLFW_KEY_W);
  EXPECT_FALSE(other.keys[0].down);
  EXPECT_TRUE(other.keys[1].down);
  EXPECT_FALSE(other.keys[2].down);
  EXPECT_NEAR(other.simulatedS, 40.0 / 60, 1e-9);
  EXPECT_NEAR(rows[69]["simulated_s"].get<double>(), 40.0 / 60, 1e-9);

  // The walk's captures (rendered offscreen from its camera) before and after: the same.
  const engine::Image before = load("walk_before.png"), after = load("walk_after.png");
  ASSERT_EQ(before.width, 320);
  ASSERT_EQ(after.width, 320);
  int largest = 0;
  long differing = 0;
  for (size_t i = 0; i < before.rgba.size() && before.rgba.size() == after.rgba.size(); ++i) {
    const int d = std::abs(int(before.rgba[i]) - int(after.rgba[i]));
    largest = std::max(largest, d);
    differing += d > 0;
  }
  std::printf("walk before and after: %ld channel values differ, by %d/255 at most\n", differing, largest);
  EXPECT_EQ(before.rgba.size(), after.rgba.size());
  EXPECT_LE(largest, 1);  // measured: 17 channel values differ, by 1/255 (the eye height's last bit)
  // The other mode's capture is the window: its magenta clear, and ImGui's window on it.
  const engine::Image window = load("other.png");
  ASSERT_EQ(window.width, 320);
  ASSERT_EQ(window.height, 180);
  auto isMagenta = [](const uint8_t* p) { return p[0] == 255 && p[1] == 0 && p[2] == 255; };
  EXPECT_TRUE(isMagenta(window.pixel(300, 160)));
  EXPECT_TRUE(isMagenta(window.pixel(10, 10)));
  long coveredByUi = 0;  // pixels of the ImGui window, (20, 20) to (220, 120)
  for (int y = 22; y < 118; ++y) {
    for (int x = 22; x < 218; ++x) coveredByUi += !isMagenta(window.pixel(x, y));
  }
  EXPECT_EQ(coveredByUi, 196 * 96);
  // ImGui's colours are sRGB-encoded values, blended and shown as they are: the window
  // background (0.06, alpha 0.94: bytes 15 and 240) over the magenta clear is
  // 15 * 240/255 + 255 * 15/255 = 29 in red and blue, 14 in green; measured (29, 14, 29).
  // (When the overlay wrote to an sRGB attachment, blending in linear light and encoding
  // once more, this measured (95, 67, 95).)
  const uint8_t* body = window.pixel(200, 100);
  std::printf("ImGui window body over magenta: (%d, %d, %d)\n", body[0], body[1], body[2]);
  EXPECT_NEAR(body[0], 29, 1);
  EXPECT_NEAR(body[1], 14, 1);
  EXPECT_NEAR(body[2], 29, 1);
}

// In the editor, Esc in the walk (the cursor free) goes back to the editor
// (WalkModeOptions::escapeTo); a mode's request switches at once.
TEST_F(ShellTest, EscapeInTheWalkGoesToTheModeItNames) {
  const engine::Scene scene = engine::makeSampleScene();
  auto shell = Shell::create(options("0 mode other\n2 mode walk\n5 key ESCAPE down\n6 key ESCAPE up\n9 quit\n"));
  ASSERT_TRUE(shell.ok()) << shell.message();
  walk::WalkModeOptions walkOptions;
  walkOptions.escapeTo = "other";
  walk::WalkMode walkMode(scene, walkOptions);
  OtherMode other;
  ASSERT_TRUE((*shell)->addMode(walkMode).ok());
  ASSERT_TRUE((*shell)->addMode(other).ok());
  auto report = (*shell)->run("walk");
  ASSERT_TRUE(report.ok()) << report.message();
  const auto rows = trace();
  ASSERT_EQ(rows.size(), 10u);
  for (int f = 0; f <= 9; ++f) EXPECT_EQ(rows[f]["mode"], f >= 2 && f < 5 ? "walk" : "other") << "frame " << f;
  EXPECT_EQ(other.enters, 2);
  EXPECT_EQ(other.leaves, 1);
  ASSERT_EQ(other.keys.size(), 1u);  // the walk took Esc down; its release came to the other
  EXPECT_EQ(other.keys[0].key, GLFW_KEY_ESCAPE);
  EXPECT_FALSE(other.keys[0].down);
}

TEST_F(ShellTest, AModeThatObjectsToClosingKeepsTheWindowAndBecomesActive) {
  const engine::Scene scene = engine::makeSampleScene();
  auto shell = Shell::create(options("5 close\n8 mode walk\n10 close\n40 quit\n"));
  ASSERT_TRUE(shell.ok()) << shell.message();
  walk::WalkMode walkMode(scene, {});
  OtherMode other;
  other.refuseCloses = 2;
  ASSERT_TRUE((*shell)->addMode(walkMode).ok());
  ASSERT_TRUE((*shell)->addMode(other).ok());
  // The window's close button, pressed before the first frame: asked, refused.
  glfwSetWindowShouldClose((*shell)->window().handle(), GLFW_TRUE);
  auto report = (*shell)->run("walk");
  ASSERT_TRUE(report.ok()) << report.message();
  const auto rows = trace();
  ASSERT_EQ(rows.size(), 11u);  // the third request (frame 10) is agreed to: no frame after it
  EXPECT_EQ(rows[0]["mode"], "other");  // the mode that asked became the active one
  EXPECT_EQ(rows[7]["mode"], "other");
  EXPECT_EQ(rows[9]["mode"], "walk");
  EXPECT_EQ(other.closeAsks, 3);
  EXPECT_FALSE(glfwWindowShouldClose((*shell)->window().handle()));  // each refusal kept it open
}

TEST_F(ShellTest, UnknownModeOrWalkEventEndsTheRunWithAnError) {
  const engine::Scene scene = engine::makeSampleScene();
  {
    auto shell = Shell::create(options("5 mode edit\n"));
    ASSERT_TRUE(shell.ok()) << shell.message();
    walk::WalkMode walkMode(scene, {});
    ASSERT_TRUE((*shell)->addMode(walkMode).ok());
    auto report = (*shell)->run("walk");
    ASSERT_FALSE(report.ok());
    EXPECT_EQ(report.message(), "replay, frame 5: no mode named 'edit' (there are: walk)");
  }
  {
    auto shell = Shell::create(options("0 mode other\n3 viewpoint 1\n"));
    ASSERT_TRUE(shell.ok()) << shell.message();
    walk::WalkMode walkMode(scene, {});
    OtherMode other;
    ASSERT_TRUE((*shell)->addMode(walkMode).ok());
    ASSERT_TRUE((*shell)->addMode(other).ok());
    auto report = (*shell)->run("walk");
    ASSERT_FALSE(report.ok());
    EXPECT_EQ(report.message(), "replay, frame 3: replay: mode 'other' has no event 'viewpoint'");
  }
}

}  // namespace
}  // namespace pw::app
