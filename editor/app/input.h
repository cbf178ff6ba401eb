// Input as a mode receives it: from the window (real input), or from a replay script
// (replay.h), which plays the same events. GLFW's codes: keys GLFW_KEY_*, buttons
// GLFW_MOUSE_BUTTON_*, modifiers GLFW_MOD_*. Positions in window pixels, origin at the
// top-left corner.
#pragma once

#include <filesystem>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

namespace pw::app {

struct KeyEvent {
  int key = -1;
  bool down = false;  // repeats are not reported
  int mods = 0;
  bool uiWantsIt = false;  // ImGui has the keyboard (a text field is active): a mode usually lets it be
};

struct MouseButtonEvent {
  int button = 0;
  bool down = false;
  int mods = 0;
  bool uiWantsIt = false;  // the pointer is over an ImGui window
};

// The pointer moved to `positionPx`.
struct CursorEvent {
  glm::dvec2 positionPx{0.0};
};

// The pointer moved by (dx, dy) pixels, as a captured (hidden) cursor reports it:
// replay scripts' `mouse DX DY`, for looking around without a position.
struct PointerMotionEvent {
  double dxPx = 0;
  double dyPx = 0;
};

struct ScrollEvent {
  glm::dvec2 offset{0.0};  // wheel steps; y > 0 away from the user
  bool uiWantsIt = false;
};

// Files dropped on the window.
struct DropEvent {
  std::vector<std::filesystem::path> paths;
};

using InputEvent = std::variant<KeyEvent, MouseButtonEvent, CursorEvent, PointerMotionEvent, ScrollEvent, DropEvent>;

// One lambda per kind for std::visit: std::visit(Overloaded{[](const KeyEvent&) {...},
// [](const auto&) {}}, event).
template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

}  // namespace pw::app
