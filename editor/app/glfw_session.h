// GLFW's process-wide state: initialised once, on first use, and terminated when the
// process exits (initialising it again after glfwTerminate sometimes failed to reach
// the X server: the presenter tests saw it).
#pragma once

#include <string>
#include <vector>

#include "base/result.h"

namespace pw::app {

// Initialises GLFW if it is not yet. Errors: no display (the message says to run on a
// desktop, or under xvfb-run), no Vulkan loader.
Status initGlfw();

// The Vulkan instance extensions a window surface needs (RendererOptions::instanceExtensions).
// Errors: as initGlfw's, or a display that cannot show Vulkan.
Result<std::vector<std::string>> windowInstanceExtensions();

// GLFW's description of its last error ("unknown GLFW error" when it has none).
std::string glfwLastError();

}  // namespace pw::app
