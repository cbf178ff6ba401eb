// The shell's replay scripts: every event kind the shell knows, a mode's own kinds,
// and errors that say where and what was expected.
#include "editor/app/replay.h"

#include <filesystem>
#include <fstream>

#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include "editor/app/key_names.h"

namespace pw::app {
namespace {
namespace fs = std::filesystem;

struct Jump {
  double heightM;
};

const std::vector<ReplayVerb> kJumpVerb = {{"jump", [](std::istream& words) -> Result<std::any> {
                                              Jump jump{};
                                              if (!(words >> jump.heightM) || jump.heightM <= 0) {
                                                return makeError("expected 'jump HEIGHT_M' with a height above 0");
                                              }
                                              return std::any(jump);
                                            }}};

// From a file: relative paths in it are relative to its folder.
TEST(ReplayGrammar, ParsesTheShellsEventsForEveryMode) {
  const fs::path dir = fs::path(PW_BINARY_DIR) / "test-output" / "app", script = dir / "every_event.replay";
  fs::create_directories(dir);
  std::ofstream(script) << "1 key LEFT_CONTROL down\n2 mouse 4 -2.5\n3 mouse right down\n4 mouse middle up\n"
                           "5 mousemove 200.5 150\n6 wheel -2\n7 drop in/shot.json\n8 resize 640 480\n"
                           "9 capture /abs/c.png\n10 mode edit\n11 quit\n12 close\n";
  const Result<std::vector<ReplayEvent>> read = readReplay(script);
  ASSERT_TRUE(read.ok()) << read.message();
  const std::vector<ReplayEvent>& e = *read;
  ASSERT_EQ(e.size(), 12u);
  EXPECT_EQ(std::get<KeyEvent>(e[0].what).key, GLFW_KEY_LEFT_CONTROL);
  EXPECT_TRUE(std::get<KeyEvent>(e[0].what).down);
  EXPECT_DOUBLE_EQ(std::get<PointerMotionEvent>(e[1].what).dyPx, -2.5);
  EXPECT_EQ(std::get<MouseButtonEvent>(e[2].what).button, GLFW_MOUSE_BUTTON_RIGHT);
  EXPECT_TRUE(std::get<MouseButtonEvent>(e[2].what).down);
  EXPECT_EQ(std::get<MouseButtonEvent>(e[3].what).button, GLFW_MOUSE_BUTTON_MIDDLE);
  EXPECT_FALSE(std::get<MouseButtonEvent>(e[3].what).down);
  EXPECT_EQ(std::get<CursorEvent>(e[4].what).positionPx, glm::dvec2(200.5, 150));
  EXPECT_EQ(std::get<ScrollEvent>(e[5].what).offset, glm::dvec2(0, -2));
  ASSERT_EQ(std::get<DropEvent>(e[6].what).paths.size(), 1u);
  EXPECT_EQ(std::get<DropEvent>(e[6].what).paths[0], dir / "in/shot.json");
  EXPECT_EQ(std::get<ResizeRequest>(e[7].what).width, 640);
  EXPECT_EQ(std::get<CaptureRequest>(e[8].what).path, "/abs/c.png");  // absolute paths stay
  EXPECT_EQ(std::get<ModeRequest>(e[9].what).mode, "edit");
  EXPECT_TRUE(std::holds_alternative<QuitRequest>(e[10].what));
  EXPECT_TRUE(std::holds_alternative<CloseRequest>(e[11].what));
  // The input among them is what a window reports; the rest is not input.
  EXPECT_TRUE(inputOf(e[0].what).has_value());
  EXPECT_TRUE(inputOf(e[6].what).has_value());
  EXPECT_FALSE(inputOf(e[7].what).has_value());
  EXPECT_FALSE(inputOf(e[9].what).has_value());
}

TEST(ReplayGrammar, TypeGivesOneCharacterPerCodePoint) {
  auto events = parseReplay("4 type 1.5\n5 type h\xc3\xb6he\n", "s.replay", ".");
  ASSERT_TRUE(events.ok()) << events.message();
  ASSERT_EQ(events->size(), 2u);
  EXPECT_EQ(std::get<TypeRequest>((*events)[0].what).codepoints, (std::vector<unsigned>{'1', '.', '5'}));
  EXPECT_EQ(std::get<TypeRequest>((*events)[1].what).codepoints, (std::vector<unsigned>{'h', 0xf6, 'h', 'e'}));
  EXPECT_FALSE(inputOf((*events)[0].what).has_value());  // characters are ImGui's, not a mode's
  auto cut = parseReplay("4 type h\xc3\n", "s", ".");
  ASSERT_FALSE(cut.ok());
  EXPECT_EQ(cut.message(), "s:1: 'type': the text is not UTF-8");
  EXPECT_FALSE(parseReplay("4 type\n", "s", ".").ok());
}

TEST(ReplayGrammar, ModesAddTheirOwnEvents) {
  auto events = parseReplay("3 jump 0.5\n1 key SPACE down\n", "s.replay", ".", kJumpVerb);
  ASSERT_TRUE(events.ok()) << events.message();
  ASSERT_EQ(events->size(), 2u);
  const auto& jump = std::get<ModeEvent>((*events)[1].what);
  EXPECT_EQ(jump.verb, "jump");
  ASSERT_NE(std::any_cast<Jump>(&jump.value), nullptr);
  EXPECT_DOUBLE_EQ(std::any_cast<Jump>(jump.value).heightM, 0.5);
  // Without the mode's verbs, the same line is an unknown event.
  auto unknown = parseReplay("3 jump 0.5\n", "s.replay", ".");
  ASSERT_FALSE(unknown.ok());
  EXPECT_EQ(unknown.message(),
            "s.replay:1: unknown event 'jump' (key, mouse, mousemove, wheel, type, drop, resize, capture, mode, quit, close)");
  // The mode's parser says what it expected, at the line.
  auto bad = parseReplay("\n# a comment\n3 jump -1\n", "s.replay", ".", kJumpVerb);
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.message(), "s.replay:3: expected 'jump HEIGHT_M' with a height above 0");
  EXPECT_FALSE(parseReplay("3 jump 1 2\n", "s", ".", kJumpVerb).ok());  // words left over
}

TEST(ReplayGrammar, ErrorsSayWhatWasExpected) {
  const std::pair<const char*, const char*> cases[] = {
      {"1 mouse left sideways", "expected 'mouse left down|up'"},
      {"1 mouse 3", "expected 'mouse DX DY' in pixels or 'mouse left|right|middle down|up'"},
      {"1 mouse 3x 4", "expected 'mouse DX DY' in pixels or 'mouse left|right|middle down|up'"},
      {"1 mousemove 3", "expected 'mousemove X Y' in window pixels"},
      {"1 wheel up", "expected 'wheel DY' in steps"},
      {"1 drop", "expected 'drop FILE'"},
      {"1 mode", "expected 'mode NAME'"},
      {"1 resize 10 20000", "expected 'resize WIDTH HEIGHT' in pixels (1..16384)"},
      {"1 key w down", "unknown key 'w' (use GLFW names: W, UP, LEFT_SHIFT, PAGE_UP, F12)"},
      {"-1 quit", "expected a frame number (0, 1, 2, ...) first, not '-1'"},
      {"1", "expected an event after the frame (key, mouse, mousemove, wheel, type, drop, resize, capture, mode, quit, close)"},
  };
  for (const auto& [line, expected] : cases) {
    auto parsed = parseReplay(line, "s", ".");
    ASSERT_FALSE(parsed.ok()) << line;
    EXPECT_EQ(parsed.message(), std::string("s:1: ") + expected) << line;
  }
}

TEST(KeyNames, AreGlfwsConstantsWithoutThePrefix) {
  EXPECT_EQ(keyCodeFromName("KP_ENTER"), GLFW_KEY_KP_ENTER);
  EXPECT_EQ(keyCodeFromName("GRAVE_ACCENT"), GLFW_KEY_GRAVE_ACCENT);
  EXPECT_EQ(keyCodeFromName("0"), GLFW_KEY_0);
  EXPECT_EQ(keyCodeFromName("F25"), GLFW_KEY_F25);
  EXPECT_EQ(keyCodeFromName("MENU"), GLFW_KEY_MENU);
  EXPECT_EQ(keyCodeFromName("LEFT_CTRL"), -1);
  EXPECT_EQ(keyName(GLFW_KEY_PAGE_DOWN), "PAGE_DOWN");
  EXPECT_EQ(keyName(GLFW_KEY_UNKNOWN), "");
  // Every name goes back to itself.
  int named = 0;
  for (int key = 0; key <= GLFW_KEY_LAST; ++key) {
    const std::string name = keyName(key);
    if (name.empty()) continue;
    ++named;
    EXPECT_EQ(keyCodeFromName(name), key) << name;
  }
  EXPECT_EQ(named, 120);  // every key GLFW 3.3 names
}

}  // namespace
}  // namespace pw::app
