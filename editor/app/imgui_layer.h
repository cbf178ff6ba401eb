// Dear ImGui (Debian's 1.86, unmodified) on a Window and a Presenter: the context, its
// GLFW and Vulkan backends, and the font (DejaVu Sans Mono when installed, else ImGui's
// built-in one). Its Vulkan backend draws inside the Presenter's overlay render pass,
// over the frame's views. One ImGuiLayer at a time (ImGui's context is global).
#pragma once

#include <array>
#include <memory>
#include <optional>

#include <vulkan/vulkan.h>

#include <glm/glm.hpp>

#include "base/result.h"
#include "editor/app/input_queue.h"
#include "engine/gpu/presenter.h"
#include "engine/gpu/renderer.h"
#include "engine/gpu/vk_owner.h"

struct GLFWwindow;

namespace pw::app {

class Window;

class ImGuiLayer {
 public:
  // Starts ImGui's GLFW backend without its input callbacks (they would write
  // io.KeysDown as events arrive, so that a key pressed and released between two frames
  // is lost): ImGui's input comes from the shell's InputQueue instead (beginFrame), and
  // the window's callbacks stay the window's. Uploads the font.
  // The window, renderer and presenter must outlive the layer.
  static Result<std::unique_ptr<ImGuiLayer>> create(Window& window, engine::Renderer& renderer,
                                                    engine::Presenter& presenter);
  ~ImGuiLayer();  // the caller waits for the frames in flight first (Presenter::waitIdle)
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;

  // The backends' new frame, then ImGui::NewFrame() with `input` (InputQueue::state():
  // the pointer, buttons, keys, wheel and characters of this frame). `live`: a pointer
  // outside the window, no button held, is reported as none (a replay's is where it
  // was moved).
  void beginFrame(const UiFrameInput& input, bool live);
  void endFrame();    // ImGui::Render()
  // Records the last endFrame()'s draw data; an overlay callback for Presenter::drawFrame.
  void record(VkCommandBuffer cmd) const;

  // The first Vulkan call of ImGui's backend that failed (its CheckVkResultFn), as an
  // error; ok while none has.
  Status status() const;

 private:
  ImGuiLayer() = default;
  engine::gpu::OwnedDescriptorPool pool_;
  GLFWwindow* window_ = nullptr;
  bool context_ = false, glfw_ = false, vulkan_ = false;
};

}  // namespace pw::app
