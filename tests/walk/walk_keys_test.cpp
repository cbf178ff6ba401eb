// photowalk walk's keys and frame options, end to end under an X server (xvfb-run) on
// lavapipe, through replay scripts, --trace and captures: PageDown/PageUp/Home, H,
// F12, Tab, --msaa, --per-pixel-lighting, and the README's "walk frame within
// 2.1/255 (sample room) and 0.9/255 (lit corridor) of its render".
// Validation is on (PW_VALIDATION=1): walk exits non-zero on any validation message.
//
// Walk launches (each a second or two of lavapipe): one script for the keys on
// tests/data/walk/viewpoints_headlight.wrl, that model again with --msaa 4, a failed
// F12, the sample room and a lit corridor each with and without --per-pixel-lighting
// --msaa 4, and two bad --msaa values.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <regex>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "engine/scene/image.h"
#include "engine/vrml/vrml_reader.h"
#include "tests/gpu/image_compare.h"
#include "tests/walk/walk_run.h"

namespace pw::walk {
namespace {
namespace fs = std::filesystem;

using test::CommandRun;

// A finished walk: what it printed, its exit code, its trace.
struct WalkRun {
  CommandRun run;
  std::vector<TraceRow> trace;
};

fs::path outputDir() { return fs::path(PW_BINARY_DIR) / "test-output" / "walk_keys"; }

// Walks `model` through `script` (written to NAME.replay; captures land beside it)
// with a trace (NAME.csv).
WalkRun walk(const std::string& model, const std::string& name, const std::string& script, const std::string& options) {
  const fs::path scriptPath = outputDir() / (name + ".replay"), tracePath = outputDir() / (name + ".csv");
  std::ofstream(scriptPath) << script;
  WalkRun w;
  w.run = photowalk("walk " + model + " --no-vsync --replay " + scriptPath.string() + " --trace " + tracePath.string() +
                    " " + options);
  w.trace = readTrace(tracePath);
  return w;
}

engine::Image load(const fs::path& path) {
  auto image = engine::loadImage(path);
  EXPECT_TRUE(image.ok()) << image.message();
  return image.ok() ? *image : engine::Image{};
}

struct Rect {
  int x0, y0, x1, y1;  // [x0, x1) x [y0, y1)
};

// Mean of R, G and B over `r`, /255.
double meanIn(const engine::Image& image, Rect r) {
  double sum = 0;
  for (int y = r.y0; y < r.y1; ++y) {
    for (int x = r.x0; x < r.x1; ++x) {
      for (int c = 0; c < 3; ++c) sum += image.pixel(x, y)[c];
    }
  }
  return sum / (3.0 * (r.x1 - r.x0) * (r.y1 - r.y0));
}

// Mean |a - b| over every pixel's R, G and B, /255 (the README's "on average").
double meanAbsDifference(const engine::Image& a, const engine::Image& b) {
  double sum = 0;
  for (size_t i = 0; i < a.rgba.size(); i += 4) {
    for (int c = 0; c < 3; ++c) sum += std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c]));
  }
  return sum / (3.0 * (a.rgba.size() / 4));
}

// Largest |a - b| over R, G and B of the pixels for which `where(x, y)` holds.
int maxDifference(const engine::Image& a, const engine::Image& b,
                  const std::function<bool(int, int)>& where = [](int, int) { return true; }) {
  int worst = 0;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      if (!where(x, y)) continue;
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(a.pixel(x, y)[c]) - int(b.pixel(x, y)[c])));
    }
  }
  return worst;
}

long countPixels(const engine::Image& image, const std::function<bool(const uint8_t*)>& test) {
  long n = 0;
  for (size_t i = 0; i < image.rgba.size(); i += 4) n += test(&image.rgba[i]);
  return n;
}

bool isBlack(const uint8_t* p) { return p[0] == 0 && p[1] == 0 && p[2] == 0; }
bool isWhite(const uint8_t* p) { return p[0] == 255 && p[1] == 255 && p[2] == 255; }
// Between black and white, clearly neither: a pixel an edge covers in part.
bool isIntermediate(const uint8_t* p) {
  return std::all_of(p, p + 3, [](uint8_t v) { return v >= 16 && v <= 239; });
}

// ---------------------------------------------------------------------------------
// The keys, on tests/data/walk/viewpoints_headlight.wrl: three viewpoints, a wall and
// floor lit by the headlight alone, a white box that glows (emissive) on a black sky.

const std::string kKeysModel = std::string(PW_SOURCE_DIR) + "/tests/data/walk/viewpoints_headlight.wrl";
constexpr int kKeysWidth = 640, kKeysHeight = 360;

// Viewpoint changes glide for 30 frames: an event at frame F lands at frame F + 29.
constexpr const char* kKeysScript =
    "10 key PAGE_DOWN down\n11 key PAGE_DOWN up\n"  // 1 -> 2, there at 39
    "50 key PAGE_DOWN down\n51 key PAGE_DOWN up\n"  // 2 -> 3, there at 79
    "90 key PAGE_UP down\n91 key PAGE_UP up\n"      // 3 -> 2, there at 119
    "130 key HOME down\n131 key HOME up\n"          // 2 -> 1, there at 159
    "170 key PAGE_UP down\n171 key PAGE_UP up\n"    // 1 -> 3 (wraps), there at 199
    "210 key PAGE_DOWN down\n211 key PAGE_DOWN up\n"  // 3 -> 1 (wraps), there at 239
    // Standing still at viewpoint 1 from here on.
    "245 capture lit.png\n"
    "250 key H down\n251 key H up\n255 capture dark.png\n"   // headlight off
    "260 key H down\n261 key H up\n265 capture relit.png\n"  // on again
    "270 key F12 down\n270 capture f12_frame.png\n271 key F12 up\n"  // screenshot 1, overlay shown
    "280 key TAB down\n281 key TAB up\n285 capture no_overlay.png\n"
    "290 key F12 down\n291 key F12 up\n"  // screenshot 2, overlay hidden
    "300 quit\n";

// Where a viewpoint puts the eye and how it looks (yaw 0 along -Z, + to the left).
struct Expected {
  double x, y, z, yawDeg, pitchDeg;
};

class WalkKeys : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    fs::remove_all(outputDir());
    fs::create_directories(outputDir() / "screenshots");
  }
  void SetUp() override {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no X display (run under xvfb-run)";
    setenv("PW_VALIDATION", "1", 1);
  }

  // The key script, walked once for all the tests that read it.
  static const WalkRun& keysWalk() {
    static const WalkRun run = walk(kKeysModel, "keys", kKeysScript,
                                    "--size " + std::to_string(kKeysWidth) + "x" + std::to_string(kKeysHeight) +
                                        " --screenshot-dir " + (outputDir() / "screenshots").string());
    return run;
  }

  // Where viewpoint `index` (from 0) of the model puts the eye, worked out here from
  // the file's axis-angle orientation (Rodrigues on the view direction (0, 0, -1)).
  static Expected viewpoint(size_t index) {
    auto scene = engine::readVrml(kKeysModel, nullptr);
    if (!scene.ok() || scene->viewpoints.size() != 3) {
      ADD_FAILURE() << kKeysModel << ": " << (scene.ok() ? "expected three viewpoints" : scene.message());
      return {};
    }
    const engine::Viewpoint& v = scene->viewpoints.at(index);
    const glm::dvec3 axis = glm::normalize(glm::dvec3(v.orientation));
    const double angle = v.orientation.w;
    const glm::dvec3 d(0, 0, -1);
    const glm::dvec3 f = d * std::cos(angle) + glm::cross(axis, d) * std::sin(angle) +
                         axis * glm::dot(axis, d) * (1 - std::cos(angle));
    return {v.position.x, v.position.y, v.position.z, glm::degrees(std::atan2(-f.x, -f.z)),
            glm::degrees(std::asin(f.y))};
  }
};

void expectAt(const TraceRow& r, const Expected& e, double tolerance) {
  EXPECT_NEAR(r.x, e.x, tolerance) << "frame " << r.frame;
  EXPECT_NEAR(r.y, e.y, tolerance) << "frame " << r.frame;
  EXPECT_NEAR(r.z, e.z, tolerance) << "frame " << r.frame;
  EXPECT_NEAR(r.yawDeg, e.yawDeg, tolerance * 100) << "frame " << r.frame;
  EXPECT_NEAR(r.pitchDeg, e.pitchDeg, tolerance * 100) << "frame " << r.frame;
}

TEST_F(WalkKeys, TheScriptRunsCleanWithValidationOn) {
  const WalkRun& w = keysWalk();
  EXPECT_EQ(w.run.exitCode, 0) << w.run.output;
  EXPECT_EQ(w.run.output.find("validation"), std::string::npos) << w.run.output;
  ASSERT_EQ(w.trace.size(), 301u);  // frames 0..300: the walk ends one frame after its last event
  EXPECT_EQ(w.trace.back().frame, 300);
}

TEST_F(WalkKeys, PageDownGlidesToTheNextViewpointInHalfASecond) {
  const auto& rows = keysWalk().trace;
  ASSERT_EQ(rows.size(), 301u);
  const Expected first = viewpoint(0), second = viewpoint(1), third = viewpoint(2);
  expectAt(rows[9], first, 1e-5);  // where the walk starts
  // A glide, not a jump: half way (ease 0.5) at frame 10 + 14, not there yet at 38.
  EXPECT_NEAR(rows[24].x, (first.x + second.x) / 2, 1e-4);
  EXPECT_NEAR(rows[24].z, (first.z + second.z) / 2, 1e-4);
  EXPECT_NEAR(rows[24].yawDeg, (first.yawDeg + second.yawDeg) / 2, 1e-2);
  for (int f = 10; f <= 38; ++f) {
    EXPECT_GT(rows[f].x, first.x) << "frame " << f;
    EXPECT_LT(rows[f].x, second.x) << "frame " << f;
  }
  EXPECT_GT(std::abs(rows[38].x - second.x), 1e-5);
  expectAt(rows[39], second, 1e-5);
  expectAt(rows[49], second, 1e-5);  // and stays
  expectAt(rows[79], third, 1e-5);   // the second PageDown
  // From the last viewpoint, PageDown wraps round to the first.
  expectAt(rows[239], first, 1e-5);
}

TEST_F(WalkKeys, PageUpGoesBackToThePreviousViewpoint) {
  const auto& rows = keysWalk().trace;
  ASSERT_EQ(rows.size(), 301u);
  expectAt(rows[89], viewpoint(2), 1e-5);   // before PageUp: the third
  expectAt(rows[119], viewpoint(1), 1e-5);  // after: the second
  EXPECT_GT(std::abs(rows[104].y - viewpoint(1).y), 1e-3);  // gliding between them
  // From the first, PageUp wraps round to the last.
  expectAt(rows[169], viewpoint(0), 1e-5);
  expectAt(rows[199], viewpoint(2), 1e-5);
}

TEST_F(WalkKeys, HomeReturnsToTheFirstViewpoint) {
  const auto& rows = keysWalk().trace;
  ASSERT_EQ(rows.size(), 301u);
  expectAt(rows[129], viewpoint(1), 1e-5);
  expectAt(rows[159], viewpoint(0), 1e-5);
  for (size_t f = 239; f < rows.size(); ++f) expectAt(rows[f], viewpoint(0), 1e-5);  // still there for the captures
}

// The headlight lights the wall and floor (their only light) and nothing else: off,
// they go black while the glowing box and the sky stay as they were; on again, the
// frame comes back.
TEST_F(WalkKeys, HeadlightKeyDarkensWhatOnlyTheHeadlightLights) {
  ASSERT_EQ(keysWalk().run.exitCode, 0) << keysWalk().run.output;
  const engine::Image lit = load(outputDir() / "lit.png"), dark = load(outputDir() / "dark.png"),
                      relit = load(outputDir() / "relit.png");
  ASSERT_EQ(lit.width, kKeysWidth);
  ASSERT_EQ(dark.width, kKeysWidth);
  ASSERT_EQ(relit.width, kKeysWidth);
  // Viewpoint 1 at 640x360: the wall spans about x 103..537, y 50..265, the box about
  // x 268..380, y 105..215; the sky is above and beside the wall.
  const Rect wall{120, 60, 250, 250}, box{295, 125, 355, 195}, sky{0, 0, 640, 40};
  // Measured: wall 204.0/255 lit (diffuse 0.8 facing the headlight), 0 dark.
  EXPECT_NEAR(meanIn(lit, wall), 204.0, 3.0);
  EXPECT_EQ(meanIn(dark, wall), 0.0);
  EXPECT_EQ(meanIn(lit, box), 255.0);
  EXPECT_EQ(meanIn(dark, box), 255.0);
  EXPECT_EQ(meanIn(lit, sky), 0.0);
  EXPECT_EQ(meanIn(dark, sky), 0.0);
  // Every pixel the key changed went black (lit by the headlight alone), and it
  // changed a good part of the frame (the wall: measured 36.5%).
  long changed = 0;
  for (int y = 0; y < lit.height; ++y) {
    for (int x = 0; x < lit.width; ++x) {
      if (std::equal(lit.pixel(x, y), lit.pixel(x, y) + 3, dark.pixel(x, y))) continue;
      ++changed;
      EXPECT_TRUE(isBlack(dark.pixel(x, y))) << "pixel " << x << ", " << y << " changed but is not black";
      if (HasFailure()) return;
    }
  }
  EXPECT_NEAR(static_cast<double>(changed) / (lit.width * lit.height), 0.365, 0.01);
  // Twice toggled: the same frame (measured: identical).
  EXPECT_LE(maxDifference(relit, lit), 1);
}

// F12 writes photowalk-YYYYMMDD-HHMMSS-N.png into --screenshot-dir: the frame at the
// window's size, as `capture` saves it.
TEST_F(WalkKeys, F12WritesTheFrameIntoTheScreenshotDir) {
  const WalkRun& w = keysWalk();
  ASSERT_EQ(w.run.exitCode, 0) << w.run.output;
  std::vector<fs::path> shots;
  for (const auto& entry : fs::directory_iterator(outputDir() / "screenshots")) shots.push_back(entry.path());
  std::sort(shots.begin(), shots.end());
  ASSERT_EQ(shots.size(), 2u);  // two presses, two files, nothing else
  const std::regex name(R"(photowalk-\d{8}-\d{6}-([12])\.png)");
  std::smatch m;
  const std::string first = shots[0].filename().string(), second = shots[1].filename().string();
  ASSERT_TRUE(std::regex_match(first, m, name)) << first;
  ASSERT_TRUE(std::regex_match(second, m, name)) << second;
  // Both presses print where the file went.
  for (const fs::path& shot : shots) {
    EXPECT_NE(w.run.output.find("screenshot: " + shot.string()), std::string::npos) << w.run.output;
  }
  const fs::path one = first.ends_with("-1.png") ? shots[0] : shots[1];
  const engine::Image screenshot = load(one), frame = load(outputDir() / "f12_frame.png");
  ASSERT_EQ(screenshot.width, kKeysWidth);
  ASSERT_EQ(screenshot.height, kKeysHeight);
  ASSERT_EQ(frame.width, kKeysWidth);
  ASSERT_EQ(frame.height, kKeysHeight);
  // The same frame as the capture at that frame (measured: identical), and a real
  // one: the lit wall and the glowing box are in it.
  EXPECT_LE(maxDifference(screenshot, frame), 1);
  EXPECT_NEAR(meanIn(screenshot, {120, 60, 250, 250}), 204.0, 3.0);
  EXPECT_EQ(meanIn(screenshot, {295, 125, 355, 195}), 255.0);
}

// Tab hides and shows the overlay (ImGui, drawn into the window's swapchain image).
// Captures and F12 screenshots are rendered offscreen from the same camera and never
// carry the overlay, so whether it is shown cannot be seen in them: what is checked
// here is that it never leaks into them, shown or hidden. (Seeing Tab's effect needs a
// read-back of the presented image, which the walk does not have.)
TEST_F(WalkKeys, OverlayNeverAppearsInCapturesOrScreenshots) {
  ASSERT_EQ(keysWalk().run.exitCode, 0) << keysWalk().run.output;
  const engine::Image shown = load(outputDir() / "lit.png"), hidden = load(outputDir() / "no_overlay.png");
  ASSERT_EQ(shown.width, kKeysWidth);
  ASSERT_EQ(hidden.width, kKeysWidth);
  EXPECT_EQ(maxDifference(shown, hidden), 0);
  // The overlay's place (top left, from (10, 10)) holds the black sky, as the scene has it.
  EXPECT_EQ(meanIn(shown, {0, 0, 300, 40}), 0.0);
  std::vector<fs::path> shots;
  for (const auto& entry : fs::directory_iterator(outputDir() / "screenshots")) shots.push_back(entry.path());
  ASSERT_EQ(shots.size(), 2u);
  EXPECT_EQ(maxDifference(load(shots[0]), load(shots[1])), 0);
}

// --msaa 4 smooths the box's outline: at 1x every pixel is black or white, at 4x the
// edge pixels take the part of the box they cover.
TEST_F(WalkKeys, Msaa4SmoothsSilhouetteEdges) {
  ASSERT_EQ(keysWalk().run.exitCode, 0) << keysWalk().run.output;
  const WalkRun w = walk(kKeysModel, "msaa4", "0 key H down\n1 key H up\n3 capture dark_msaa4.png\n4 quit\n",
                         "--size " + std::to_string(kKeysWidth) + "x" + std::to_string(kKeysHeight) + " --msaa 4");
  ASSERT_EQ(w.run.exitCode, 0) << w.run.output;
  EXPECT_NE(w.run.output.find(", 4x MSAA,"), std::string::npos) << w.run.output;
  EXPECT_NE(keysWalk().run.output.find(", 1x MSAA,"), std::string::npos) << keysWalk().run.output;
  const engine::Image one = load(outputDir() / "dark.png"), four = load(outputDir() / "dark_msaa4.png");
  ASSERT_EQ(one.width, kKeysWidth);
  ASSERT_EQ(four.width, kKeysWidth);
  // Headlight off: the glowing box on black. The outline's length in pixels: white
  // pixels of the 1x frame with a black 4-neighbour (measured 361).
  long outline = 0;
  for (int y = 1; y + 1 < one.height; ++y) {
    for (int x = 1; x + 1 < one.width; ++x) {
      if (!isWhite(one.pixel(x, y))) continue;
      outline += isBlack(one.pixel(x - 1, y)) || isBlack(one.pixel(x + 1, y)) || isBlack(one.pixel(x, y - 1)) ||
                 isBlack(one.pixel(x, y + 1));
    }
  }
  const long between1 = countPixels(one, isIntermediate), between4 = countPixels(four, isIntermediate);
  const long white1 = countPixels(one, isWhite);
  EXPECT_NEAR(outline, 361, 15);
  EXPECT_EQ(between1, 0);  // measured 0
  // At 4x: 273 (measured), three in four outline pixels; 10% margin.
  EXPECT_NEAR(between4, 273, 27);
  // The same box: the area it covers agrees within a fraction of the outline
  // (measured 10112.2 at 4x, 10044 white pixels at 1x: 0.19 of the outline).
  double area4 = 0;
  for (size_t i = 0; i < four.rgba.size(); i += 4) area4 += four.rgba[i] / 255.0;
  EXPECT_NEAR(area4, static_cast<double>(white1), outline * 0.3);
}

// A failed F12 (the screenshot folder is a file) is a message, in the window and as one
// warning line, and the walk goes on to its end.
TEST_F(WalkKeys, FailedScreenshotIsAMessageAndTheWalkGoesOn) {
  const fs::path notAFolder = outputDir() / "not_a_folder";
  std::ofstream(notAFolder) << "a file\n";
  const WalkRun w = walk(kKeysModel, "f12_fails", "5 key F12 down\n6 key F12 up\n40 quit\n",
                         "--size 320x180 --screenshot-dir " + notAFolder.string());
  EXPECT_EQ(w.run.exitCode, 0) << w.run.output;
  const std::regex oneLine("(^|\n)warning: screenshot not saved: " + notAFolder.string() +
                           R"(/photowalk-\d{8}-\d{6}-1\.png: cannot write: Not a directory\n)");
  EXPECT_TRUE(std::regex_search(w.run.output, oneLine)) << w.run.output;
  EXPECT_EQ(w.run.output.find("error:"), std::string::npos) << w.run.output;
  ASSERT_FALSE(w.trace.empty());
  EXPECT_EQ(w.trace.back().frame, 40);  // not 5: the walk went on after the key
}

TEST_F(WalkKeys, BadMsaaIsAOneLineError) {
  for (const char* samples : {"3", "abc"}) {
    const WalkRun w = walk(kKeysModel, std::string("msaa_") + samples, "10 quit\n", std::string("--size 320x180 --msaa ") + samples);
    EXPECT_EQ(w.run.exitCode, 1) << samples << ": " << w.run.output;
    EXPECT_EQ(w.run.output.rfind("error: ", 0), 0u) << w.run.output;
    EXPECT_EQ(std::count(w.run.output.begin(), w.run.output.end(), '\n'), 1) << w.run.output;
    EXPECT_NE(w.run.output.find(samples), std::string::npos) << w.run.output;
  }
}

// ---------------------------------------------------------------------------------
// The walk frame against `photowalk render` of the same viewpoint at the same size.

constexpr const char* kFrameSize = "1280x720";

class WalkFrame : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { fs::create_directories(outputDir()); }
  void SetUp() override {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no X display (run under xvfb-run)";
    setenv("PW_VALIDATION", "1", 1);
  }

  struct Comparison {
    double meanAbs = -1;  // /255
    test::TileDifference tiles;
    std::string summary;  // walk's last line: MSAA, filtering, lighting
  };

  // Captures the walk frame at viewpoint 1 of `model` (where the walk starts) and
  // renders the same viewpoint; NAME_walk.png, NAME_render.png.
  static Comparison compare(const std::string& model, const std::string& name, const std::string& options) {
    Comparison c;
    const WalkRun w = walk(model, name, "0 capture " + name + "_walk.png\n1 quit\n",
                           std::string("--size ") + kFrameSize + " " + options);
    EXPECT_EQ(w.run.exitCode, 0) << w.run.output;
    c.summary = w.run.output;
    const fs::path rendered = outputDir() / (name + "_render.png");
    const CommandRun r = photowalk("render " + model + " --viewpoint 1 --size " + kFrameSize + " -o " + rendered.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    const engine::Image a = load(outputDir() / (name + "_walk.png")), b = load(rendered);
    EXPECT_EQ(a.width, 1280);
    EXPECT_EQ(b.width, 1280);
    if (a.width != b.width || a.height != b.height || a.empty()) return c;
    c.meanAbs = meanAbsDifference(a, b);
    c.tiles = test::compareTiles(a, b, 16, 9);
    std::printf("%s (%s): mean |walk - render| %.4f/255; %s\n", name.c_str(), options.c_str(), c.meanAbs,
                c.tiles.describe().c_str());
    return c;
  }
};

// README: "the sample room's walk frame is within 2.1/255 of its render on average".
// Measured at 1280x720, viewpoint 1 (lavapipe, 2 cores): 1.554/255 (2.111 at 640x360,
// the README's figure). Its worst 80x80 tile (of 16x9) differs by 30.9/255 in mean
// colour: the shiny pyramid, whose three-vertex faces spread the highlight when lit per
// vertex. With per-pixel lighting and 4x MSAA 0.746/255 (what remains is the render's
// anisotropic filtering), worst tile 1.00/255; per-pixel lighting alone 0.832, 4x MSAA
// alone 1.472.
TEST_F(WalkFrame, SampleRoomWithinItsMeasuredFigureOfTheRender) {
  const Comparison plain = compare("sample", "sample", "");
  EXPECT_NE(plain.summary.find("1x MSAA, trilinear filtering, lit per vertex"), std::string::npos) << plain.summary;
  EXPECT_NEAR(plain.meanAbs, 1.554, 0.1);
  EXPECT_NEAR(plain.tiles.worst, 30.9, 1.5);

  const Comparison full = compare("sample", "sample_full", "--per-pixel-lighting --msaa 4");
  EXPECT_NE(full.summary.find("4x MSAA, trilinear filtering, lit per pixel"), std::string::npos) << full.summary;
  // Closer with both; each alone (0.832, 1.472) would miss this.
  EXPECT_NEAR(full.meanAbs, 0.746, 0.05);
  EXPECT_LT(full.meanAbs, plain.meanAbs - 0.6);
  EXPECT_LE(full.tiles.worst, 1.0 + 0.2);
}

// README: "a lit photowalk corridor within 0.9/255". Measured at 1280x720, viewpoint 1
// ("Photo") of `build assets/corridor.json --lit`: 0.339/255, worst tile 0.886/255
// (0.262 and 0.68 before the corridor was closed behind the camera: the closing wall
// and the textured strips are lit per vertex too). With per-pixel lighting and 4x MSAA: identical to the render (its
// textures, cut from the photo, are filtered alike in both); per-pixel lighting alone
// 0.050, 4x MSAA alone 0.215.
TEST_F(WalkFrame, LitCorridorWithinItsMeasuredFigureOfTheRender) {
  const fs::path model = outputDir() / "lit_corridor" / "corridor.wrl";
  fs::remove_all(model.parent_path());
  fs::create_directories(model.parent_path());
  const CommandRun built = photowalk("build " + std::string(PW_SOURCE_DIR) + "/assets/corridor.json --lit -o " + model.string());
  ASSERT_EQ(built.exitCode, 0) << built.output;

  const Comparison plain = compare(model.string(), "corridor", "");
  EXPECT_NE(plain.summary.find("1x MSAA, trilinear filtering, lit per vertex"), std::string::npos) << plain.summary;
  EXPECT_NEAR(plain.meanAbs, 0.339, 0.05);
  EXPECT_NEAR(plain.tiles.worst, 0.886, 0.15);

  const Comparison full = compare(model.string(), "corridor_full", "--per-pixel-lighting --msaa 4");
  EXPECT_NE(full.summary.find("4x MSAA, trilinear filtering, lit per pixel"), std::string::npos) << full.summary;
  EXPECT_GE(full.meanAbs, 0.0);
  EXPECT_LE(full.meanAbs, 0.01);
  EXPECT_LE(full.tiles.worst, 0.01);
}

}  // namespace
}  // namespace pw::walk
