// The editor's stand-up tool (issue 25, part 3), end to end under an X server (xvfb-run)
// on lavapipe: on the random corridor with a person (tests/groundtruth: TUNE seed 0, its
// exact corners), U and a rectangle dragged around the person keep a cutout in the shot;
// undo and redo take it away and back; a rectangle running off the photo's bottom edge is
// refused with the reason and changes nothing; a name typed into the list is kept; the
// saved copy carries the cutout and `photowalk build` stands the person up from it, as
// tall as she is. Validation on (PW_VALIDATION=1).
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/edit/edit_run.h"

namespace pw::edit::test {
namespace {
namespace fs = std::filesystem;
using pw::test::CommandRun;

constexpr int kWidth = 1280, kHeight = 1000;  // the 3D preview hidden (P): the whole panel in view

class StandUp : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::path(PW_BINARY_DIR) / "test-output" / "edit_stand_up";
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    const fs::path random = fs::path(PW_GROUNDTRUTH_DIR) / "random";
    fs::copy_file(random / "seed_00000.png", dir_ / "seed_00000.png");
    fs::copy_file(random / "seed_00000.json", dir_ / "seed_00000.json");
  }
  void SetUp() override {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no X display (run under xvfb-run)";
    setenv("PW_VALIDATION", "1", 1);
  }
  std::vector<Row> edit(const std::string& name, const std::string& script, std::string* output = nullptr,
                        const std::string& file = "seed_00000.json") {
    const fs::path scriptPath = dir_ / (name + ".replay"), tracePath = dir_ / (name + ".jsonl");
    std::ofstream(scriptPath) << "0 key P down\n0 key P up\n" << script;
    fs::remove(tracePath);
    const CommandRun run = photowalk("edit " + (dir_ / file).string() + " --size " + std::to_string(kWidth) + "x" +
                                     std::to_string(kHeight) + " --no-vsync --replay " + scriptPath.string() +
                                     " --trace " + tracePath.string());
    EXPECT_EQ(run.exitCode, 0) << run.output;
    if (output) *output = run.output;
    return readTrace(tracePath);
  }
  static fs::path dir_;
};
fs::path StandUp::dir_;

TEST_F(StandUp, ARectangleAroundAPersonStandsHerUpUndoneRedoneNamedAndSaved) {
  const nlohmann::json truth = nlohmann::json::parse(std::ifstream(dir_ / "seed_00000.json"));
  nlohmann::json person;
  for (const nlohmann::json& o : truth.at("objects"))
    if (o.at("kind") == "person") person = o;
  ASSERT_FALSE(person.is_null());
  const glm::dvec2 head(person["keypoints_px"]["head_top"][0], person["keypoints_px"]["head_top"][1]);
  const glm::dvec2 feet(person["keypoints_px"]["feet"][0], person["keypoints_px"]["feet"][1]);
  const double halfWidthPx = 0.7 * (feet.y - head.y) * person["size_m"][0].get<double>() / person["size_m"][1].get<double>();
  // A person's rough rectangle around her (photo pixels): from above her head to below her feet.
  const glm::dvec2 from(feet.x - halfWidthPx, head.y - 8), to(feet.x + halfWidthPx, feet.y + 10);

  const auto first = edit("layout", "2 quit\n");
  ASSERT_GE(first.size(), 2u);
  const Row& r = first.back();
  const glm::dvec2 a = r.toWindow(from), b = r.toWindow(to);
  const glm::dvec2 bottom = r.toWindow({feet.x, double(truth["image_size"][1]) - 20.0});

  Script s;
  s.key(3, "U");
  s.drag(5, a, b - a, 6);                                // frames 5-12: the rectangle around her
  s.at(14, "capture standing.png");
  s.ctrlKey(16, "Z");                                    // undo
  s.ctrlKey(19, "Z", true);                              // redo
  s.drag(22, bottom, glm::dvec2(40, 60), 4);             // off the photo's bottom edge: refused
  s.at(30, "save-copy standing.json").at(32, "quit");
  std::string output;
  const auto rows = edit("stand_up", s.str(), &output);
  ASSERT_GE(rows.size(), 32u);
  const auto cutouts = [&](size_t frame) { return rows.at(frame).raw.at("cutouts"); };
  EXPECT_TRUE(rows.at(4).raw.at("outlining").at("active").get<bool>());
  EXPECT_TRUE(rows.at(8).raw.at("outlining").at("from_px").is_array()) << "dragging";
  ASSERT_EQ(cutouts(14).size(), 1u) << cutouts(14).dump();
  EXPECT_EQ(cutouts(14)[0].at("name"), "object 1");
  const nlohmann::json outline = cutouts(14)[0].at("outline_px");
  ASSERT_EQ(outline.size(), 4u);
  EXPECT_NEAR(outline[0][0].get<double>(), from.x, 1.0 / r.scale + 0.01) << outline.dump();
  EXPECT_NEAR(outline[2][1].get<double>(), to.y, 1.0 / r.scale + 0.01) << outline.dump();
  EXPECT_TRUE(rows.at(14).dirty);
  EXPECT_EQ(cutouts(18).size(), 0u) << "undone";
  EXPECT_EQ(cutouts(21).size(), 1u) << "redone";
  EXPECT_EQ(cutouts(29).size(), 1u) << "the rectangle off the bottom edge was kept";
  EXPECT_NE(output.find("stand up: cutout \"object 2\": it runs off the photo's bottom edge"), std::string::npos) << output;
  EXPECT_NE(output.find("stood up object 1: 1.9"), std::string::npos) << output;

  // Named in the list, kept on Enter (one undo step).
  const auto& widgets = rows.at(29).raw.at("camera").at("widgets");
  ASSERT_TRUE(widgets.contains("cutout 1")) << widgets.dump();
  Script n;
  n.click(3, widgets["cutout 1"]).ctrlKeyHeld(5, "A").at(10, "type person").key(12, "ENTER");
  n.at(15, "save-copy named.json").at(17, "quit");
  const auto named = edit("name", n.str(), nullptr, "standing.json");
  ASSERT_GE(named.size(), 17u);
  EXPECT_EQ(named.at(16).raw.at("cutouts")[0].at("name"), "person") << named.at(16).raw.at("cutouts").dump();

  // The saved copy stands her up in `build`: as tall as she is (1.945 m).
  const fs::path saved = dir_ / "named.json";
  ASSERT_TRUE(fs::exists(saved));
  const CommandRun built = photowalk("build " + saved.string() + " -o " + (dir_ / "model.wrl").string());
  ASSERT_EQ(built.exitCode, 0) << built.output;
  std::ifstream model(dir_ / "model.wrl");
  const std::string text((std::istreambuf_iterator<char>(model)), std::istreambuf_iterator<char>());
  std::smatch m;
  ASSERT_TRUE(std::regex_search(text, m, std::regex("stood up: person \\([^)]*\\), a cut-out [0-9.]+ m wide and ([0-9.]+) m high")))
      << "no 'stood up' line in the model";
  EXPECT_NEAR(std::stod(m[1]), person["size_m"][1].get<double>(), 0.03);
}

}  // namespace
}  // namespace pw::edit::test
