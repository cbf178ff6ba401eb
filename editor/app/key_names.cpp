#include "editor/app/key_names.h"

#include <unordered_map>
#include <utility>
#include <vector>

#include <GLFW/glfw3.h>

namespace pw::app {
namespace {

#define PW_KEY(name) {#name, GLFW_KEY_##name}

const std::vector<std::pair<std::string, int>>& keyTable() {
  static const std::vector<std::pair<std::string, int>> kKeys = {
      PW_KEY(SPACE), PW_KEY(APOSTROPHE), PW_KEY(COMMA), PW_KEY(MINUS), PW_KEY(PERIOD), PW_KEY(SLASH),
      PW_KEY(0), PW_KEY(1), PW_KEY(2), PW_KEY(3), PW_KEY(4), PW_KEY(5), PW_KEY(6), PW_KEY(7), PW_KEY(8), PW_KEY(9),
      PW_KEY(SEMICOLON), PW_KEY(EQUAL),
      PW_KEY(A), PW_KEY(B), PW_KEY(C), PW_KEY(D), PW_KEY(E), PW_KEY(F), PW_KEY(G), PW_KEY(H), PW_KEY(I), PW_KEY(J),
      PW_KEY(K), PW_KEY(L), PW_KEY(M), PW_KEY(N), PW_KEY(O), PW_KEY(P), PW_KEY(Q), PW_KEY(R), PW_KEY(S), PW_KEY(T),
      PW_KEY(U), PW_KEY(V), PW_KEY(W), PW_KEY(X), PW_KEY(Y), PW_KEY(Z),
      PW_KEY(LEFT_BRACKET), PW_KEY(BACKSLASH), PW_KEY(RIGHT_BRACKET), PW_KEY(GRAVE_ACCENT),
      PW_KEY(WORLD_1), PW_KEY(WORLD_2),
      PW_KEY(ESCAPE), PW_KEY(ENTER), PW_KEY(TAB), PW_KEY(BACKSPACE), PW_KEY(INSERT), PW_KEY(DELETE),
      PW_KEY(RIGHT), PW_KEY(LEFT), PW_KEY(DOWN), PW_KEY(UP), PW_KEY(PAGE_UP), PW_KEY(PAGE_DOWN), PW_KEY(HOME),
      PW_KEY(END), PW_KEY(CAPS_LOCK), PW_KEY(SCROLL_LOCK), PW_KEY(NUM_LOCK), PW_KEY(PRINT_SCREEN), PW_KEY(PAUSE),
      PW_KEY(F1), PW_KEY(F2), PW_KEY(F3), PW_KEY(F4), PW_KEY(F5), PW_KEY(F6), PW_KEY(F7), PW_KEY(F8), PW_KEY(F9),
      PW_KEY(F10), PW_KEY(F11), PW_KEY(F12), PW_KEY(F13), PW_KEY(F14), PW_KEY(F15), PW_KEY(F16), PW_KEY(F17),
      PW_KEY(F18), PW_KEY(F19), PW_KEY(F20), PW_KEY(F21), PW_KEY(F22), PW_KEY(F23), PW_KEY(F24), PW_KEY(F25),
      PW_KEY(KP_0), PW_KEY(KP_1), PW_KEY(KP_2), PW_KEY(KP_3), PW_KEY(KP_4), PW_KEY(KP_5), PW_KEY(KP_6),
      PW_KEY(KP_7), PW_KEY(KP_8), PW_KEY(KP_9), PW_KEY(KP_DECIMAL), PW_KEY(KP_DIVIDE), PW_KEY(KP_MULTIPLY),
      PW_KEY(KP_SUBTRACT), PW_KEY(KP_ADD), PW_KEY(KP_ENTER), PW_KEY(KP_EQUAL),
      PW_KEY(LEFT_SHIFT), PW_KEY(LEFT_CONTROL), PW_KEY(LEFT_ALT), PW_KEY(LEFT_SUPER), PW_KEY(RIGHT_SHIFT),
      PW_KEY(RIGHT_CONTROL), PW_KEY(RIGHT_ALT), PW_KEY(RIGHT_SUPER), PW_KEY(MENU)};
  return kKeys;
}

#undef PW_KEY

}  // namespace

int keyCodeFromName(const std::string& name) {
  static const std::unordered_map<std::string, int> kByName(keyTable().begin(), keyTable().end());
  auto it = kByName.find(name);
  return it == kByName.end() ? -1 : it->second;
}

std::string keyName(int key) {
  for (const auto& [name, code] : keyTable()) {
    if (code == key) return name;
  }
  return "";
}

}  // namespace pw::app
