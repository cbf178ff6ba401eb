// Drawing the Renderer's views (view.h) to a window's swapchain. The window code
// (GLFW, in editor/) creates the VkSurfaceKHR with renderer.instance() and passes it
// in borrowed; it must destroy the Presenter before the surface, and both before the
// Renderer. pw_gpu never sees GLFW or ImGui.
//
// Per frame: the views are drawn in order into the swapchain image with dynamic
// rendering (scene views multisampled and resolved), then `overlay` records into
// overlayRenderPass() on that image (load, store), which is what ImGui 1.86's Vulkan
// backend needs:
//   ImGui_ImplVulkan_InitInfo info{...renderer.device(), queue(), ...};
//   info.MinImageCount = presenter.minImageCount(); info.ImageCount = presenter.imageCount();
//   ImGui_ImplVulkan_Init(&info, presenter.overlayRenderPass());
//   presenter.drawFrame({ImageView{photo, {zoom, pan}, canvas}, SceneView{model, camera, preview}},
//                       [](VkCommandBuffer cmd) { ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd); });
// The render pass outlives swapchain recreation (its format only changes if the
// surface's does, which a resize does not do).
//
// Colour encoding. ImGui 1.86's backend writes its colours, which are sRGB-encoded
// values, straight to the framebuffer; on an sRGB attachment the hardware would encode
// them once more (ImGui's default window background 15/255 showed as 67, a handle
// (70, 220, 90) as (143, 239, 160)). So the overlay pass targets a UNORM format
// wherever the surface allows. Where the device offers VK_KHR_swapchain_mutable_format
// (Debian 12's lavapipe does) the swapchain images are sRGB, the views draw into them
// as into any sRGB target (blending, MSAA resolve and the clear in linear light,
// exactly as the offscreen renders they are compared with), and the overlay pass
// writes through a UNORM view of the same image, its values unchanged. Chosen over a
// UNORM swapchain with the views encoding in their shaders (PW_SPEC_ENCODE_SRGB),
// which blends and resolves encoded values: measured on lavapipe (forced, gpu.Views),
// the sample room in the window then had only 89% of pixels within 2/255 of its
// offscreen render (largest difference 56/255; cause not pinned down) against the
// tests' 99%. That remains the fallback on a device without the extension: UNORM
// images, the views' shaders encoding sRGB, the overlay writing unchanged (right
// colours for ImGui, a less exact scene).
//
// The views lie under ImGui: an application shows the photo or a 3D preview inside an
// ImGui window by giving that window no background (ImGuiWindowFlags_NoBackground)
// and drawing the view into the window's content rectangle, which ImGui reports in
// the same frame pixels (scaled by io.DisplayFramebufferScale). Handles, lines and
// text then go on top with ImGui's draw lists. (Not ImDrawList::AddCallback with a
// pipeline of ours: 1.86's backend draws inside its own VkRenderPass with its own
// pipeline and descriptor state, and binds only its font texture.)
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include <vulkan/vulkan.h>

#include "base/result.h"
#include "engine/gpu/renderer.h"
#include "engine/gpu/view.h"
#include "engine/scene/image.h"

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

  // Draws `views` in order (each over what the ones before left), `overlay` on top,
  // and queues the frame for presentation; pixels no view covers are `clearColor`
  // (sRGB-encoded). Out-of-date and suboptimal swapchains (resizes) are handled here
  // by recreating them; they are not errors. Errors: a view Renderer::renderViews
  // would refuse (checked before anything is acquired or recorded).
  Status drawFrame(const std::vector<View>& views, const OverlayCallback& overlay = {},
                   const glm::vec3& clearColor = glm::vec3(0.0f));
  // The default scene over the whole window: drawFrame({SceneView{defaultScene, camera, {}, settings}}).
  Status drawFrame(const Camera& camera, const FrameSettings& settings, const OverlayCallback& overlay = {});

  // What the window shows, overlay included: the next drawn frame copies its image,
  // after the overlay, into host memory; takeCapture() then waits for that frame and
  // returns it as RGBA8, sRGB-encoded as shown (a BGRA swapchain is reordered), opaque,
  // rows top to bottom. Errors: nothing asked for, no frame drawn since (minimised), a
  // surface whose images cannot be copied.
  void captureNextFrame();
  Result<Image> takeCapture();

  // Waits until the GPU has finished every frame this Presenter submitted (before
  // tearing down what an overlay callback used, e.g. ImGui's backend).
  Status waitIdle();

  VkRenderPass overlayRenderPass() const;  // its attachment is UNORM (see above)
  uint32_t imageCount() const;
  uint32_t minImageCount() const;
  VkFormat format() const;  // the swapchain images' (sRGB with the mutable-format extension)
  VkExtent2D extent() const;
  uint64_t framesPresented() const;
  FrameStats lastFrameStats() const;  // summed over the last frame's scene views

  struct Impl;

 private:
  explicit Presenter(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace pw::engine
