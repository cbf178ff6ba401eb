// The path input takes to ImGui, live or replayed: a queue of the window's (or a
// replay's) events and characters, handed on one frame's worth at a time. (The modes
// get each event as it comes; the shell: shell.h.)
//
// ImGui 1.86's old key API sees a key or a mouse button only as it is when a frame
// starts (io.KeysDown[], io.MouseDown[]): a key pressed and released between two frames
// is lost, and so is the Enter that ends a field. The queue hands each frame the events
// in order up to, not including, the first that would make a second transition of the
// same key or button in that frame (a key down and up go in two frames), a character
// after a key that text fields act on (Enter, Backspace, arrows: ImGui takes a frame's
// characters before its keys), or a pointer move after a button's transition (the
// press is where the pointer was); the rest wait for the next frame. ImGui thus sees
// every transition, in order, at any frame rate. No ImGui here: headless-tested.
//
//   queue.push(KeyEvent{GLFW_KEY_ENTER, true});  queue.push(KeyEvent{GLFW_KEY_ENTER, false});
//   auto first = queue.takeFrame();   // Enter down; state().keys[GLFW_KEY_ENTER] is true
//   auto second = queue.takeFrame();  // Enter up
#pragma once

#include <array>
#include <cstddef>
#include <deque>
#include <optional>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

#include "editor/app/input.h"

namespace pw::app {

// A character typed (GLFW's char callback, a replay's `type TEXT`): a Unicode code point.
struct CharEvent {
  unsigned codepoint = 0;
};

using QueuedInput = std::variant<InputEvent, CharEvent>;

// What ImGui is given for one frame.
struct UiFrameInput {
  std::optional<glm::dvec2> cursorPx;  // unset: no position reported yet
  std::array<bool, 5> buttons{};       // by GLFW_MOUSE_BUTTON_* (ImGui's io.MouseDown)
  std::array<bool, 512> keys{};        // by GLFW key code (ImGui 1.86's io.KeysDown)
  glm::dvec2 wheel{0.0};               // steps in this frame
  std::vector<unsigned> characters;    // typed in this frame, in order
};

class InputQueue {
 public:
  void push(const InputEvent& event) { pending_.emplace_back(event); }
  void push(CharEvent c) { pending_.emplace_back(c); }

  // This frame's events, oldest first (see above); state() then holds what ImGui sees.
  std::vector<QueuedInput> takeFrame();
  const UiFrameInput& state() const { return state_; }

  bool empty() const { return pending_.empty(); }
  size_t pending() const { return pending_.size(); }

 private:
  std::deque<QueuedInput> pending_;
  UiFrameInput state_;
};

// True for keys that ImGui's text fields act on when pressed (Enter, Tab, Backspace,
// Delete, arrows, Home, End, Page Up/Down, Escape, Insert): those that type nothing.
bool isEditingKey(int key);

}  // namespace pw::app
