#include "editor/app/window.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include "editor/app/glfw_session.h"
#include "engine/gpu/vk_check.h"

namespace pw::app {

Window::Window(GLFWwindow* window, VkInstance instance) : window_(window), instance_(instance) {}

Window::~Window() {
  if (surface_ != VK_NULL_HANDLE) vkDestroySurfaceKHR(instance_, surface_, nullptr);
  if (window_) glfwDestroyWindow(window_);
}

Window& Window::of(GLFWwindow* window) { return *static_cast<Window*>(glfwGetWindowUserPointer(window)); }

Result<std::unique_ptr<Window>> Window::create(const WindowOptions& options, VkInstance instance) {
  PW_TRY(initGlfw());
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  GLFWwindow* handle = glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
  if (!handle) return makeError("cannot open a window: " + glfwLastError());
  std::unique_ptr<Window> window(new Window(handle, instance));
  const VkResult result = glfwCreateWindowSurface(instance, handle, nullptr, &window->surface_);
  if (result != VK_SUCCESS) {
    window->surface_ = VK_NULL_HANDLE;
    return makeError(std::string("cannot open a window: no Vulkan surface for it (") +
                     engine::gpu::vkResultName(result) + ": " + glfwLastError() + ")");
  }

  glfwSetWindowUserPointer(handle, window.get());
  glfwSetKeyCallback(handle, [](GLFWwindow* w, int key, int, int action, int mods) {
    if (action != GLFW_REPEAT) of(w).emit(KeyEvent{key, action == GLFW_PRESS, mods});
  });
  glfwSetCharCallback(handle, [](GLFWwindow* w, unsigned codepoint) {
    Window& self = of(w);
    if (self.onChar_) self.onChar_(codepoint);
  });
  glfwSetMouseButtonCallback(handle, [](GLFWwindow* w, int button, int action, int mods) {
    of(w).emit(MouseButtonEvent{button, action == GLFW_PRESS, mods});
  });
  glfwSetCursorPosCallback(handle, [](GLFWwindow* w, double x, double y) { of(w).emit(CursorEvent{{x, y}}); });
  glfwSetScrollCallback(handle, [](GLFWwindow* w, double dx, double dy) { of(w).emit(ScrollEvent{{dx, dy}}); });
  glfwSetDropCallback(handle, [](GLFWwindow* w, int count, const char** paths) {
    DropEvent drop;
    for (int i = 0; i < count; ++i) drop.paths.emplace_back(paths[i]);
    of(w).emit(drop);
  });
  glfwSetFramebufferSizeCallback(handle, [](GLFWwindow* w, int width, int height) {
    Window& self = of(w);
    if (self.onFramebufferSize_) self.onFramebufferSize_({width, height});
  });
  return window;
}

glm::ivec2 Window::framebufferSize() const {
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  return {width, height};
}

bool Window::closeRequested() const { return glfwWindowShouldClose(window_); }

void Window::cancelClose() { glfwSetWindowShouldClose(window_, GLFW_FALSE); }

void Window::setCursorCaptured(bool captured) {
  glfwSetInputMode(window_, GLFW_CURSOR, captured ? GLFW_CURSOR_DISABLED : GLFW_CURSOR_NORMAL);
}

glm::ivec2 Window::resizeAndWait(int width, int height) {
  glfwSetWindowSize(window_, width, height);
  for (int i = 0; i < 50; ++i) {
    glfwPollEvents();
    if (framebufferSize() == glm::ivec2(width, height)) break;
    glfwWaitEventsTimeout(0.01);
  }
  return framebufferSize();
}

}  // namespace pw::app
