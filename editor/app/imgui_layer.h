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
#include "engine/gpu/presenter.h"
#include "engine/gpu/renderer.h"
#include "engine/gpu/vk_owner.h"

namespace pw::app {

class Window;

// What ImGui sees of a replay's input (replay.h): while a replay plays it replaces what
// the window reports, so that scripted clicks and keys reach ImGui's widgets.
struct ReplayedUiInput {
  std::optional<glm::dvec2> cursorPx;  // unset: the pointer is not over the window
  std::array<bool, 3> buttons{};       // GLFW_MOUSE_BUTTON_LEFT, RIGHT, MIDDLE
  glm::dvec2 wheel{0.0};               // steps since the last frame
  std::array<bool, 512> keys{};        // by GLFW key code (ImGui 1.86's io.KeysDown)
};

class ImGuiLayer {
 public:
  // Installs ImGui's GLFW callbacks on the window (they pass input on to the window's
  // own, which must be installed first: Window::create does it) and uploads the font.
  // The window, renderer and presenter must outlive the layer.
  static Result<std::unique_ptr<ImGuiLayer>> create(Window& window, engine::Renderer& renderer,
                                                    engine::Presenter& presenter);
  ~ImGuiLayer();  // the caller waits for the frames in flight first (Presenter::waitIdle)
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;

  // The backends' new frame, then ImGui::NewFrame(); `replayed` set: ImGui's mouse and
  // keys are those instead of the window's.
  void beginFrame(const ReplayedUiInput* replayed = nullptr);
  void endFrame();    // ImGui::Render()
  // Records the last endFrame()'s draw data; an overlay callback for Presenter::drawFrame.
  void record(VkCommandBuffer cmd) const;

  // The first Vulkan call of ImGui's backend that failed (its CheckVkResultFn), as an
  // error; ok while none has.
  Status status() const;

 private:
  ImGuiLayer() = default;
  engine::gpu::OwnedDescriptorPool pool_;
  bool context_ = false, glfw_ = false, vulkan_ = false;
};

}  // namespace pw::app
