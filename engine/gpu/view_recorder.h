// Recording a frame's views (view.h) into a frame's colour image, in order: scene
// views (into the frame or a render target) and image views. Shared by offscreen
// frames (Renderer::renderViews) and the Presenter; internal to pw_gpu. What the
// handles name comes from Renderer::Impl (renderer_impl.h).
#pragma once

#include <memory>
#include <vector>

#include <vulkan/vulkan.h>

#include "base/result.h"
#include "engine/gpu/frame_slot.h"
#include "engine/gpu/gpu_scene.h"
#include "engine/gpu/renderer.h"
#include "engine/gpu/scene_pass.h"
#include "engine/gpu/view.h"
#include "engine/gpu/view_image.h"

namespace pw::engine {

// What a frame draws into: its single-sampled colour image (a swapchain image, or the
// offscreen result), and the frame-sized multisampled colour and depth images scene
// views use.
struct FrameTarget {
  VkImage image = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
  VkImage msaa = VK_NULL_HANDLE;  // when the renderer multisamples, else null
  VkImageView msaaView = VK_NULL_HANDLE;
  VkImage depth = VK_NULL_HANDLE;
  VkImageView depthView = VK_NULL_HANDLE;
  VkFormat format = VK_FORMAT_R8G8B8A8_SRGB;
  VkExtent2D extent{0, 0};
  bool encodeSrgbInShader = false;  // a UNORM image: shaders write sRGB-encoded values
};

class ViewRecorder {
 public:
  // Checks `views` for a frame of `extent` and finds what their handles name. Errors
  // name the view at fault (counting from 0): an unknown or removed handle, a target
  // that is not a render target, a camera that cannot project, a rectangle beyond the
  // device's viewport limits, a scale that is not a positive number. Call it before
  // acquiring a swapchain image, so that a bad view never leaves one acquired.
  Status prepare(const Renderer::Impl& renderer, const std::vector<View>& views, VkExtent2D extent);

  // Records the prepared views into `cmd` (begun; `views` as given to prepare). The
  // frame image's earlier contents are discarded (it may be in any layout, last used at
  // the colour-output or copy stage); pixels no view covers get `clearColor`
  // (sRGB-encoded). Afterwards the image is in COLOR_ATTACHMENT_OPTIMAL, written at the
  // colour-output stage. The scenes and images used are added to slot.inFlight.
  Status record(VkCommandBuffer cmd, Renderer::Impl& renderer, gpu::FrameSlot& slot, const FrameTarget& target,
                const glm::vec3& clearColor);

  const FrameStats& stats() const { return stats_; }

 private:
  struct Prepared {
    const View* view = nullptr;
    std::shared_ptr<const gpu::GpuScene> scene;  // scene views
    std::shared_ptr<const gpu::ViewImage> image;  // image views: the image; scene views: the render target, if any
    gpu::ViewArea where;
  };
  std::vector<Prepared> prepared_;
  gpu::DrawScratch scratch_;
  FrameStats stats_;
};

}  // namespace pw::engine
