// A GLFW window that Vulkan draws into: the window and its VkSurfaceKHR, created on
// a Renderer's instance. Its input goes to one handler, reached through the window's
// user pointer (no static state), so that several windows, tests and the app shell
// each get their own.
//
//   auto extensions = windowInstanceExtensions();          // glfw_session.h
//   options.instanceExtensions = *extensions;  auto renderer = Renderer::create(options);
//   auto window = Window::create({1280, 720, "photowalk"}, (*renderer)->instance());
//   auto presenter = Presenter::create(**renderer, (*window)->surface(), size.x, size.y);
// Destroy the Presenter before the Window (its surface), and the Window before the
// Renderer (the instance).
#pragma once

#include <functional>
#include <memory>
#include <string>

#include <vulkan/vulkan.h>

#include <glm/glm.hpp>

#include "base/result.h"
#include "editor/app/input.h"

struct GLFWwindow;

namespace pw::app {

struct WindowOptions {
  int width = 1280;  // screen coordinates (pixels on X11)
  int height = 720;
  std::string title = "photowalk";
};

class Window {
 public:
  // Errors: no display, no Vulkan loader, no surface for this window on `instance`.
  static Result<std::unique_ptr<Window>> create(const WindowOptions& options, VkInstance instance);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  GLFWwindow* handle() const { return window_; }
  VkSurfaceKHR surface() const { return surface_; }
  glm::ivec2 framebufferSize() const;  // pixels; 0 x 0 while minimised
  bool closeRequested() const;
  void cancelClose();  // the close button was answered: the window stays

  // Where input goes (key repeats are dropped); a handler set again replaces the last.
  void setInputHandler(std::function<void(const InputEvent&)> handler) { onInput_ = std::move(handler); }
  // Where typed characters go (GLFW's char callback: Unicode code points).
  void setCharHandler(std::function<void(unsigned)> handler) { onChar_ = std::move(handler); }
  // Called when the framebuffer's size changes (a resize, minimising).
  void setFramebufferSizeHandler(std::function<void(glm::ivec2)> handler) { onFramebufferSize_ = std::move(handler); }

  // Hides the cursor and reports unbounded motion (mouse look), or shows it again.
  void setCursorCaptured(bool captured);

  // Asks the window system for a new size and waits (up to half a second) until the
  // framebuffer has it, so that what follows sees it; returns the framebuffer size.
  glm::ivec2 resizeAndWait(int width, int height);

 private:
  Window(GLFWwindow* window, VkInstance instance);
  static Window& of(GLFWwindow* window);
  void emit(const InputEvent& event) {
    if (onInput_) onInput_(event);
  }

  GLFWwindow* window_ = nullptr;
  VkInstance instance_ = VK_NULL_HANDLE;
  VkSurfaceKHR surface_ = VK_NULL_HANDLE;
  std::function<void(const InputEvent&)> onInput_;
  std::function<void(unsigned)> onChar_;
  std::function<void(glm::ivec2)> onFramebufferSize_;
};

}  // namespace pw::app
