// Descriptor set layouts, the one pipeline layout, samplers and the graphics
// pipelines, created on first use per (colour format, sample count, variant) and
// kept for the Renderer's life.
#pragma once

#include <initializer_list>
#include <map>
#include <span>
#include <tuple>

#include <vulkan/vulkan.h>

#include "base/result.h"
#include "engine/gpu/context.h"
#include "engine/gpu/scene_packing.h"
#include "engine/gpu/vk_owner.h"

namespace pw::engine::gpu {

inline constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

// What differs between photowalk's graphics pipelines (the scene's, the image views');
// createGraphicsPipeline adds the rest: dynamic rendering into one colour attachment
// (and a depth attachment when depthFormat is set), one viewport and one scissor.
struct GraphicsPipelineParts {
  const VkPipelineShaderStageCreateInfo* stages = nullptr;  // vertex and fragment
  const VkPipelineVertexInputStateCreateInfo* vertexInput = nullptr;
  const VkPipelineInputAssemblyStateCreateInfo* assembly = nullptr;
  const VkPipelineRasterizationStateCreateInfo* raster = nullptr;
  const VkPipelineMultisampleStateCreateInfo* multisample = nullptr;
  const VkPipelineDepthStencilStateCreateInfo* depth = nullptr;
  const VkPipelineColorBlendStateCreateInfo* blend = nullptr;
  const VkPipelineDynamicStateCreateInfo* dynamic = nullptr;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkFormat colorFormat = VK_FORMAT_UNDEFINED;
  VkFormat depthFormat = VK_FORMAT_UNDEFINED;
};
Result<OwnedPipeline> createGraphicsPipeline(VkDevice device, const GraphicsPipelineParts& parts);

// The pieces a pipeline library makes its pipelines from.
Result<OwnedShaderModule> makeShader(VkDevice device, std::span<const uint32_t> words);
Result<OwnedDescriptorSetLayout> makeSetLayout(VkDevice device, std::initializer_list<VkDescriptorSetLayoutBinding> bindings);
Result<OwnedPipelineLayout> makePipelineLayout(VkDevice device, std::span<const VkDescriptorSetLayout> sets,
                                               const VkPushConstantRange& push);

class PipelineLibrary {
 public:
  // `anisotropic`: anisotropic filtering where the device has it. `vertexLighting`:
  // VRML lighting per vertex rather than per pixel (PW_SPEC_VERTEX_LIGHTING).
  static Result<std::unique_ptr<PipelineLibrary>> create(const Context& context, bool anisotropic, bool vertexLighting);

  VkDescriptorSetLayout frameSetLayout() const { return frameSetLayout_.get(); }
  VkDescriptorSetLayout sceneSetLayout() const { return sceneSetLayout_.get(); }
  VkDescriptorSetLayout textureSetLayout() const { return textureSetLayout_.get(); }
  VkPipelineLayout layout() const { return layout_.get(); }
  // The sampler for a texture. Textures cut from a photo (Texture::sourceFromTexCoord)
  // pass their footprint as explicit gradients (scene.frag); a CPU device's anisotropic
  // filter ignores those (llvmpipe takes its own from the implicit derivatives, which
  // blurred brick walls seen from the photo's camera by 14 dB), so there they are
  // filtered trilinearly.
  VkSampler sampler(TextureWrap s, TextureWrap t, bool cutFromPhoto) const {
    const bool anisotropic = !(cutFromPhoto && cpuDevice_);
    return samplers_[(s == TextureWrap::kClamp ? 1 : 0) + (t == TextureWrap::kClamp ? 2 : 0) + (anisotropic ? 4 : 0)].get();
  }
  bool anisotropic() const { return anisotropic_; }
  bool vertexLighting() const { return vertexLighting_; }

  // The pipeline for drawing `variant` into a colour target of `format` with `samples`
  // and a kDepthFormat depth target, dynamic rendering.
  Result<VkPipeline> pipeline(VkFormat format, VkSampleCountFlagBits samples, PipelineVariant variant);

 private:
  explicit PipelineLibrary(const Context& context) : context_(context) {}
  const Context& context_;
  OwnedDescriptorSetLayout frameSetLayout_;
  OwnedDescriptorSetLayout sceneSetLayout_;
  OwnedDescriptorSetLayout textureSetLayout_;
  OwnedPipelineLayout layout_;
  OwnedShaderModule vertexShader_;
  OwnedShaderModule fragmentShader_;
  bool anisotropic_ = false;
  bool vertexLighting_ = false;
  bool cpuDevice_ = false;
  std::array<OwnedSampler, 8> samplers_;  // by wrap s, wrap t, anisotropic (when enabled)
  std::map<std::tuple<VkFormat, VkSampleCountFlagBits, int>, OwnedPipeline> pipelines_;
};

}  // namespace pw::engine::gpu
