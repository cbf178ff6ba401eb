// Drawing a 2D image (an ImageView, view.h) into a rectangle of the frame: a
// triangle that covers the rectangle, and image.frag, which maps each frame pixel to
// the image through the pan/zoom transform. The pipelines (one per colour format),
// their layout and the two samplers (trilinear, nearest) live here.
#pragma once

#include <map>
#include <memory>

#include <vulkan/vulkan.h>

#include "base/result.h"
#include "engine/gpu/context.h"
#include "engine/gpu/view.h"
#include "engine/gpu/vk_owner.h"

namespace pw::engine::gpu {

class ImagePipelines {
 public:
  static Result<std::unique_ptr<ImagePipelines>> create(const Context& context);

  // Set PW_SET_IMAGE: one combined image sampler for the fragment shader.
  VkDescriptorSetLayout setLayout() const { return setLayout_.get(); }
  VkPipelineLayout layout() const { return layout_.get(); }
  // Clamp to edge; kSmooth: linear within and between mip levels; kNearest: nearest
  // texel of the nearest level.
  VkSampler sampler(ImageFilter filter) const {
    return filter == ImageFilter::kNearest ? nearest_.get() : smooth_.get();
  }

  // The pipeline drawing into a single-sampled colour target of `format` (no depth),
  // blending over what is there, or, for an opaque image on an opaque background,
  // writing (blending cost lavapipe 2 ms of a 1280x720 frame). Made on first use.
  Result<VkPipeline> pipeline(VkFormat format, bool blended);

 private:
  explicit ImagePipelines(const Context& context) : context_(context) {}
  const Context& context_;
  OwnedDescriptorSetLayout setLayout_;
  OwnedPipelineLayout layout_;
  OwnedShaderModule vertexShader_;
  OwnedShaderModule fragmentShader_;
  OwnedSampler smooth_;
  OwnedSampler nearest_;
  std::map<std::pair<VkFormat, bool>, OwnedPipeline> pipelines_;
};

// Where and how one ImageView is drawn; `set` is the image's descriptor set for the
// filter chosen (ViewImage::set).
struct ImageDraw {
  VkImageView target = VK_NULL_HANDLE;  // COLOR_ATTACHMENT_OPTIMAL, single-sampled
  VkFormat format = VK_FORMAT_UNDEFINED;
  VkRect2D area{};  // the view's rectangle clipped to the target, not empty
  VkDescriptorSet set = VK_NULL_HANDLE;
  glm::uvec2 imageSize{1};
  bool opaqueImage = false;  // every pixel's alpha is 1
  ImageTransform transform;
  glm::vec4 background{0.0f};  // sRGB-encoded as in ImageView
};

// Records the view inside a rendering instance of its own over `area` (the target's
// contents kept). The caller orders it after earlier writes to the target.
Status recordImageView(VkCommandBuffer cmd, ImagePipelines& pipelines, const ImageDraw& draw);

}  // namespace pw::engine::gpu
