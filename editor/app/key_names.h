// Key names as GLFW spells its constants without the prefix: "W" is GLFW_KEY_W,
// "LEFT_SHIFT" GLFW_KEY_LEFT_SHIFT, "PAGE_UP", "F12", "KP_ENTER". Replay scripts name
// keys this way.
#pragma once

#include <string>

namespace pw::app {

// GLFW's key code for a name, -1 if GLFW has no such key (names are upper case).
int keyCodeFromName(const std::string& name);

// The name of a GLFW key code ("" for a code without one).
std::string keyName(int key);

}  // namespace pw::app
