#include "editor/app/glfw_session.h"

#include <GLFW/glfw3.h>

namespace pw::app {
namespace {

struct GlfwSession {
  bool ok = false;
  std::string error;
  GlfwSession() {
    ok = glfwInit() == GLFW_TRUE;
    if (!ok) error = glfwLastError();
  }
  ~GlfwSession() {
    if (ok) glfwTerminate();
  }
};

}  // namespace

std::string glfwLastError() {
  const char* description = nullptr;
  glfwGetError(&description);
  return description ? description : "unknown GLFW error";
}

Status initGlfw() {
  static const GlfwSession session;  // torn down at exit, after every window
  if (!session.ok) {
    return makeError("cannot open a window: " + session.error +
                     " (no display? run on a desktop, or under xvfb-run for tests)");
  }
  if (!glfwVulkanSupported()) return makeError("cannot open a window: GLFW finds no Vulkan loader");
  return {};
}

Result<std::vector<std::string>> windowInstanceExtensions() {
  PW_TRY(initGlfw());
  uint32_t count = 0;
  const char** extensions = glfwGetRequiredInstanceExtensions(&count);
  if (!extensions) return makeError("cannot open a window: this display cannot show Vulkan (" + glfwLastError() + ")");
  return std::vector<std::string>(extensions, extensions + count);
}

}  // namespace pw::app
