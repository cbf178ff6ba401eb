// The shell's input queue (editor/app/input_queue.h): each frame gets the events up to
// the first second transition of a key or button, so that ImGui 1.86, which sees keys
// only as they are when a frame starts, sees every press and release, in order.
#include "editor/app/input_queue.h"

#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

namespace pw::app {
namespace {

KeyEvent key(int code, bool down) { return KeyEvent{code, down}; }

size_t taken(InputQueue& queue) { return queue.takeFrame().size(); }

TEST(InputQueue, AKeyDownAndUpInOneFrameGoInTwo) {
  InputQueue queue;
  queue.push(key(GLFW_KEY_ENTER, true));
  queue.push(key(GLFW_KEY_ENTER, false));
  EXPECT_EQ(taken(queue), 1u);
  EXPECT_TRUE(queue.state().keys[GLFW_KEY_ENTER]);  // ImGui sees Enter held for a frame
  EXPECT_EQ(taken(queue), 1u);
  EXPECT_FALSE(queue.state().keys[GLFW_KEY_ENTER]);
  EXPECT_TRUE(queue.empty());
  EXPECT_EQ(taken(queue), 0u);
}

TEST(InputQueue, TypingQuicklyKeepsEveryCharacterInOrderAndEnterAfterThem) {
  // "1.5" and Enter, all between two frames: each key down, its character, key up.
  InputQueue queue;
  const std::pair<int, char> typed[] = {{GLFW_KEY_1, '1'}, {GLFW_KEY_PERIOD, '.'}, {GLFW_KEY_5, '5'}};
  for (const auto& [code, c] : typed) {
    queue.push(key(code, true));
    queue.push(CharEvent{unsigned(c)});
    queue.push(key(code, false));
  }
  queue.push(key(GLFW_KEY_ENTER, true));
  queue.push(key(GLFW_KEY_ENTER, false));
  std::string text;
  int enterFrame = -1, frames = 0;
  while (!queue.empty() && frames < 20) {
    queue.takeFrame();
    for (unsigned c : queue.state().characters) {
      EXPECT_EQ(enterFrame, -1) << "a character after Enter";
      text += char(c);
    }
    if (queue.state().keys[GLFW_KEY_ENTER] && enterFrame < 0) enterFrame = frames;
    ++frames;
  }
  EXPECT_EQ(text, "1.5");
  EXPECT_GE(enterFrame, 0);
  EXPECT_FALSE(queue.state().keys[GLFW_KEY_ENTER]);
}

TEST(InputQueue, ACharacterAfterAnEditingKeyWaitsForTheNextFrame) {
  // ImGui takes a frame's characters before its keys: Backspace then "x" must not be "x" then Backspace.
  InputQueue queue;
  queue.push(key(GLFW_KEY_BACKSPACE, true));
  queue.push(CharEvent{'x'});
  EXPECT_EQ(taken(queue), 1u);
  EXPECT_TRUE(queue.state().characters.empty());
  EXPECT_EQ(taken(queue), 1u);
  ASSERT_EQ(queue.state().characters.size(), 1u);
  EXPECT_EQ(queue.state().characters[0], unsigned('x'));
  EXPECT_TRUE(queue.state().keys[GLFW_KEY_BACKSPACE]);  // still held
}

TEST(InputQueue, AClickInOneFrameIsPressedWhereThePointerWas) {
  InputQueue queue;
  queue.push(CursorEvent{{100, 50}});
  queue.push(MouseButtonEvent{GLFW_MOUSE_BUTTON_LEFT, true});
  queue.push(CursorEvent{{300, 70}});
  queue.push(MouseButtonEvent{GLFW_MOUSE_BUTTON_LEFT, false});
  EXPECT_EQ(taken(queue), 2u);
  EXPECT_TRUE(queue.state().buttons[GLFW_MOUSE_BUTTON_LEFT]);
  EXPECT_EQ(*queue.state().cursorPx, glm::dvec2(100, 50));
  EXPECT_EQ(taken(queue), 2u);
  EXPECT_FALSE(queue.state().buttons[GLFW_MOUSE_BUTTON_LEFT]);
  EXPECT_EQ(*queue.state().cursorPx, glm::dvec2(300, 70));
}

TEST(InputQueue, AShortcutsModifierIsHeldInTheFrameOfItsKey) {
  // Ctrl down, A down, Ctrl up, A up in one frame: ImGui must see Ctrl+A together.
  InputQueue queue;
  queue.push(key(GLFW_KEY_LEFT_CONTROL, true));
  queue.push(key(GLFW_KEY_A, true));
  queue.push(key(GLFW_KEY_LEFT_CONTROL, false));
  queue.push(key(GLFW_KEY_A, false));
  EXPECT_EQ(taken(queue), 2u);
  EXPECT_TRUE(queue.state().keys[GLFW_KEY_LEFT_CONTROL] && queue.state().keys[GLFW_KEY_A]);
  EXPECT_EQ(taken(queue), 2u);
  EXPECT_FALSE(queue.state().keys[GLFW_KEY_LEFT_CONTROL] || queue.state().keys[GLFW_KEY_A]);
}

TEST(InputQueue, EventsWithoutConflictsGoInOneFrameAndTheWheelAddsUp) {
  InputQueue queue;
  queue.push(key(GLFW_KEY_W, true));
  queue.push(ScrollEvent{{0, 1}});
  queue.push(ScrollEvent{{0, 2}});
  queue.push(MouseButtonEvent{GLFW_MOUSE_BUTTON_RIGHT, true});
  queue.push(DropEvent{{"a.json"}});
  EXPECT_EQ(taken(queue), 5u);
  EXPECT_EQ(queue.state().wheel, glm::dvec2(0, 3));
  EXPECT_EQ(taken(queue), 0u);
  EXPECT_EQ(queue.state().wheel, glm::dvec2(0, 0));  // the wheel is per frame; keys and buttons stay
  EXPECT_TRUE(queue.state().keys[GLFW_KEY_W]);
  EXPECT_TRUE(queue.state().buttons[GLFW_MOUSE_BUTTON_RIGHT]);
}

}  // namespace
}  // namespace pw::app
