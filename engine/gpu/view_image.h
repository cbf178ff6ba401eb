// An image that ImageViews draw (view.h): a photo uploaded with its full mip chain,
// or a render target that SceneViews draw into. Immutable once made; frames hold a
// shared_ptr to the ones they use, as they do for scenes (gpu_scene.h).
//
// Layouts: the colour image is SHADER_READ_ONLY_OPTIMAL whenever no command is using
// it. A scene view into a render target takes it to COLOR_ATTACHMENT_OPTIMAL and back
// (view_recorder.cpp); the barriers there order it after earlier reads and before
// later ones, in this frame or the next.
#pragma once

#include <memory>
#include <optional>

#include <vulkan/vulkan.h>

#include "base/result.h"
#include "engine/gpu/context.h"
#include "engine/gpu/image_pass.h"
#include "engine/gpu/resources.h"
#include "engine/gpu/upload_queue.h"
#include "engine/scene/image.h"

namespace pw::engine::gpu {

inline constexpr VkFormat kViewImageFormat = VK_FORMAT_R8G8B8A8_SRGB;  // sampled in linear light

struct ViewImage {
  // Copies `image` into a staging buffer on this thread; the copy to the GPU and the
  // mip blits are submitted through `uploads` without waiting. Errors: an empty image,
  // one larger than the device allows.
  static Result<std::shared_ptr<const ViewImage>> upload(const Context& context, const ImagePipelines& pipelines,
                                                         const Image& image, UploadQueue& uploads);
  // A width x height colour target (and its depth, and a multisampled colour image when
  // `samples` > 1) cleared to transparent black; the clear is submitted through `uploads`.
  static Result<std::shared_ptr<const ViewImage>> renderTarget(const Context& context, const ImagePipelines& pipelines,
                                                               uint32_t width, uint32_t height,
                                                               VkSampleCountFlagBits samples, UploadQueue& uploads);

  uint32_t width() const { return color.spec.width; }
  uint32_t height() const { return color.spec.height; }
  bool isRenderTarget() const { return depth.has_value(); }
  bool opaque = false;  // a photo whose every alpha is 255 (render targets: false)
  VkDescriptorSet set(ImageFilter filter) const { return filter == ImageFilter::kNearest ? nearestSet : smoothSet; }

  GpuImage color;                   // kViewImageFormat, sampled
  std::optional<GpuImage> msaa;     // render targets drawn multisampled: resolved into `color`
  std::optional<GpuImage> depth;    // render targets
  OwnedDescriptorPool descriptorPool;  // after the images it describes: freed first
  VkDescriptorSet smoothSet = VK_NULL_HANDLE;
  VkDescriptorSet nearestSet = VK_NULL_HANDLE;
};

}  // namespace pw::engine::gpu
