#include "editor/app/input_queue.h"

#include <GLFW/glfw3.h>

namespace pw::app {

bool isEditingKey(int key) {
  switch (key) {
    case GLFW_KEY_ENTER:
    case GLFW_KEY_KP_ENTER:
    case GLFW_KEY_TAB:
    case GLFW_KEY_BACKSPACE:
    case GLFW_KEY_DELETE:
    case GLFW_KEY_LEFT:
    case GLFW_KEY_RIGHT:
    case GLFW_KEY_UP:
    case GLFW_KEY_DOWN:
    case GLFW_KEY_HOME:
    case GLFW_KEY_END:
    case GLFW_KEY_PAGE_UP:
    case GLFW_KEY_PAGE_DOWN:
    case GLFW_KEY_ESCAPE:
    case GLFW_KEY_INSERT:
      return true;
    default:
      return false;
  }
}

namespace {

bool isModifier(int key) {
  return key == GLFW_KEY_LEFT_CONTROL || key == GLFW_KEY_RIGHT_CONTROL || key == GLFW_KEY_LEFT_SHIFT ||
         key == GLFW_KEY_RIGHT_SHIFT || key == GLFW_KEY_LEFT_ALT || key == GLFW_KEY_RIGHT_ALT ||
         key == GLFW_KEY_LEFT_SUPER || key == GLFW_KEY_RIGHT_SUPER;
}

}  // namespace

std::vector<QueuedInput> InputQueue::takeFrame() {
  state_.wheel = glm::dvec2(0.0);
  state_.characters.clear();
  std::array<bool, 512> keyMoved{};
  std::array<bool, 5> buttonMoved{};
  // editingKeyPressed: Enter, an arrow, a shortcut (Ctrl+A); keyPressed: any key not a modifier.
  bool editingKeyPressed = false, keyPressed = false, anyButtonMoved = false;
  std::vector<QueuedInput> taken;
  while (!pending_.empty()) {
    const QueuedInput& next = pending_.front();
    bool fits = true;
    if (const auto* c = std::get_if<CharEvent>(&next)) {
      if (editingKeyPressed) break;  // ImGui would take it before that key
      state_.characters.push_back(c->codepoint);
    } else {
      const InputEvent& event = std::get<InputEvent>(next);
      if (const auto* k = std::get_if<KeyEvent>(&event)) {
        if (k->key >= 0 && size_t(k->key) < keyMoved.size()) {
          const bool modifier = isModifier(k->key);
          if (keyMoved[k->key] || (modifier && keyPressed)) {
            fits = false;  // a second transition; a modifier changed after the key it modifies
          } else if (state_.keys[k->key] != k->down) {
            const auto& keys = state_.keys;
            const bool shortcut = keys[GLFW_KEY_LEFT_CONTROL] || keys[GLFW_KEY_RIGHT_CONTROL] ||
                                  keys[GLFW_KEY_LEFT_SUPER] || keys[GLFW_KEY_RIGHT_SUPER];
            keyMoved[k->key] = true;
            state_.keys[k->key] = k->down;
            if (k->down && !modifier) {
              keyPressed = true;
              if (shortcut || isEditingKey(k->key)) editingKeyPressed = true;
            }
          }
        }
      } else if (const auto* b = std::get_if<MouseButtonEvent>(&event)) {
        if (b->button >= 0 && size_t(b->button) < buttonMoved.size()) {
          if (buttonMoved[b->button]) {
            fits = false;
          } else if (state_.buttons[b->button] != b->down) {
            buttonMoved[b->button] = anyButtonMoved = true;
            state_.buttons[b->button] = b->down;
          }
        }
      } else if (const auto* m = std::get_if<CursorEvent>(&event)) {
        if (anyButtonMoved) {
          fits = false;
        } else {
          state_.cursorPx = m->positionPx;
        }
      } else if (const auto* s = std::get_if<ScrollEvent>(&event)) {
        state_.wheel += s->offset;
      }
    }
    if (!fits) break;
    taken.push_back(next);
    pending_.pop_front();
  }
  return taken;
}

}  // namespace pw::app
