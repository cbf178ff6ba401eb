// Drawing the Renderer's scene to a window's swapchain. The window code (GLFW, in
// editor/) creates the VkSurfaceKHR with renderer.instance() and passes it in
// borrowed; it must destroy the Presenter before the surface, and both before the
// Renderer. pw_gpu never sees GLFW or ImGui.
//
// Per frame: the scene is drawn (multisampled) and resolved into the swapchain image
// with dynamic rendering, then `overlay` records into overlayRenderPass() on that
// image (load, store), which is what ImGui 1.86's Vulkan backend needs:
//   ImGui_ImplVulkan_InitInfo info{...renderer.device(), queue(), ...};
//   info.MinImageCount = presenter.minImageCount(); info.ImageCount = presenter.imageCount();
//   ImGui_ImplVulkan_Init(&info, presenter.overlayRenderPass());
//   presenter.drawFrame(camera, {}, [](VkCommandBuffer cmd) {
//     ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd); });
// The render pass outlives swapchain recreation (its format only changes if the
// surface's does, which a resize does not do).
#pragma once

#include <functional>
#include <memory>

#include <vulkan/vulkan.h>

#include "base/result.h"
#include "engine/gpu/renderer.h"

namespace pw::engine {

// Called inside overlayRenderPass() on the frame's command buffer.
using OverlayCallback = std::function<void(VkCommandBuffer)>;

enum class PresentMode {
  kVsync,       // FIFO: always available, no tearing
  kLowLatency,  // MAILBOX, else IMMEDIATE, else FIFO
};

struct PresenterOptions {
  PresentMode mode = PresentMode::kVsync;
  int framesInFlight = 2;
};

class Presenter {
 public:
  // Errors: a device that cannot present to this surface, a Renderer created without
  // VK_KHR_surface among its instance extensions.
  static Result<std::unique_ptr<Presenter>> create(Renderer& renderer, VkSurfaceKHR surface, int width, int height,
                                                   const PresenterOptions& options = {});
  ~Presenter();
  Presenter(const Presenter&) = delete;
  Presenter& operator=(const Presenter&) = delete;

  // The window's framebuffer size in pixels, when it changes; the swapchain is remade
  // at the next drawFrame. 0 x 0 (minimised) makes drawFrame skip frames.
  void resize(int width, int height);

  // Draws one frame and queues it for presentation. Out-of-date and suboptimal
  // swapchains (resizes) are handled here by recreating them; they are not errors.
  Status drawFrame(const Camera& camera, const FrameSettings& settings, const OverlayCallback& overlay = {});

  // Waits until the GPU has finished every frame this Presenter submitted (before
  // tearing down what an overlay callback used, e.g. ImGui's backend).
  Status waitIdle();

  VkRenderPass overlayRenderPass() const;
  uint32_t imageCount() const;
  uint32_t minImageCount() const;
  VkFormat format() const;
  VkExtent2D extent() const;
  uint64_t framesPresented() const;
  FrameStats lastFrameStats() const;

  struct Impl;

 private:
  explicit Presenter(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace pw::engine
