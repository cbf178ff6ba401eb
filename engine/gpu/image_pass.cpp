#include "engine/gpu/image_pass.h"

#include "engine/scene/color_space.h"
#include "engine/gpu/pipelines.h"
#include "engine/gpu/vk_check.h"
#include "shaders/shader_interface.h"
#include "shaders/spirv.h"

namespace pw::engine::gpu {
namespace {

Result<OwnedSampler> makeSampler(VkDevice device, VkFilter filter, VkSamplerMipmapMode mipmap) {
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = filter;
  info.minFilter = filter;
  info.mipmapMode = mipmap;
  info.addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.maxAnisotropy = 1.0f;
  info.minLod = 0.0f;
  info.maxLod = VK_LOD_CLAMP_NONE;
  VkSampler sampler = VK_NULL_HANDLE;
  PW_VK_CHECK(vkCreateSampler(device, &info, nullptr, &sampler));
  return OwnedSampler(device, sampler);
}

bool isSrgbFormat(VkFormat f) {
  return f == VK_FORMAT_R8G8B8A8_SRGB || f == VK_FORMAT_B8G8R8A8_SRGB || f == VK_FORMAT_A8B8G8R8_SRGB_PACK32;
}

}  // namespace

Result<std::unique_ptr<ImagePipelines>> ImagePipelines::create(const Context& context) {
  const VkDevice device = context.device();
  std::unique_ptr<ImagePipelines> lib(new ImagePipelines(context));
  const VkDescriptorSetLayoutBinding binding{PW_BINDING_IMAGE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                                             VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
  auto setLayout = makeSetLayout(device, {binding});
  if (!setLayout) return setLayout.error();
  lib->setLayout_ = std::move(*setLayout);

  static_assert(PW_SET_IMAGE == 0, "the layout's only set");
  const VkPushConstantRange push{VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(ImagePushConstants)};
  const VkDescriptorSetLayout sets[] = {lib->setLayout_.get()};
  auto layout = makePipelineLayout(device, sets, push);
  if (!layout) return layout.error();
  lib->layout_ = std::move(*layout);

  auto vert = makeShader(device, shaders::imageVertSpirv());
  if (!vert) return vert.error();
  lib->vertexShader_ = std::move(*vert);
  auto frag = makeShader(device, shaders::imageFragSpirv());
  if (!frag) return frag.error();
  lib->fragmentShader_ = std::move(*frag);
  auto smooth = makeSampler(device, VK_FILTER_LINEAR, VK_SAMPLER_MIPMAP_MODE_LINEAR);
  if (!smooth) return smooth.error();
  lib->smooth_ = std::move(*smooth);
  auto nearest = makeSampler(device, VK_FILTER_NEAREST, VK_SAMPLER_MIPMAP_MODE_NEAREST);
  if (!nearest) return nearest.error();
  lib->nearest_ = std::move(*nearest);
  return lib;
}

Result<VkPipeline> ImagePipelines::pipeline(VkFormat format, bool blended) {
  const auto key = std::pair(format, blended);
  if (auto found = pipelines_.find(key); found != pipelines_.end()) return found->second.get();

  const VkBool32 encodeSrgb = isSrgbFormat(format) ? VK_FALSE : VK_TRUE;
  const VkSpecializationMapEntry entry{PW_SPEC_ENCODE_SRGB, 0, sizeof(VkBool32)};
  const VkSpecializationInfo specialization{1, &entry, sizeof(encodeSrgb), &encodeSrgb};
  const VkPipelineShaderStageCreateInfo stages[] = {
      {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, VK_SHADER_STAGE_VERTEX_BIT, vertexShader_.get(), "main", nullptr},
      {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, VK_SHADER_STAGE_FRAGMENT_BIT, fragmentShader_.get(), "main", &specialization},
  };
  VkPipelineVertexInputStateCreateInfo vertexInput{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = VK_CULL_MODE_NONE;
  raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  VkPipelineColorBlendAttachmentState blend{};
  blend.blendEnable = blended ? VK_TRUE : VK_FALSE;
  blend.srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
  blend.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
  blend.colorBlendOp = VK_BLEND_OP_ADD;
  blend.srcAlphaBlendFactor = VK_BLEND_FACTOR_ZERO;  // the frame stays as opaque as it was
  blend.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
  blend.alphaBlendOp = VK_BLEND_OP_ADD;
  blend.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  VkPipelineColorBlendStateCreateInfo blendState{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  blendState.attachmentCount = 1;
  blendState.pAttachments = &blend;
  const VkDynamicState dynamics[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dynamic.dynamicStateCount = 2;
  dynamic.pDynamicStates = dynamics;
  auto pipeline = createGraphicsPipeline(context_.device(), {stages, &vertexInput, &assembly, &raster, &multisample, &depth,
                                                            &blendState, &dynamic, layout_.get(), format});
  if (!pipeline) return pipeline.error();
  return pipelines_.emplace(key, std::move(*pipeline)).first->second.get();
}

Status recordImageView(VkCommandBuffer cmd, ImagePipelines& pipelines, const ImageDraw& draw) {
  // Alpha 1 everywhere (an opaque image, an opaque background): nothing to blend with.
  auto pipeline = pipelines.pipeline(draw.format, !(draw.opaqueImage && draw.background.a >= 1.0f));
  if (!pipeline) return pipeline.error();
  VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  color.imageView = draw.target;
  color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
  color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
  rendering.renderArea = draw.area;
  rendering.layerCount = 1;
  rendering.colorAttachmentCount = 1;
  rendering.pColorAttachments = &color;
  vkCmdBeginRendering(cmd, &rendering);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, *pipeline);
  const VkViewport viewport{float(draw.area.offset.x), float(draw.area.offset.y), float(draw.area.extent.width),
                            float(draw.area.extent.height), 0.0f, 1.0f};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &draw.area);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines.layout(), PW_SET_IMAGE, 1, &draw.set, 0, nullptr);
  ImagePushConstants push{};
  const float scale = static_cast<float>(draw.transform.scale);
  push.transform = glm::vec4(scale, scale, glm::vec2(draw.transform.offset));
  push.imageSize = glm::vec4(float(draw.imageSize.x), float(draw.imageSize.y), 0.0f, 0.0f);
  push.background = glm::vec4(srgbToLinear(glm::vec3(draw.background)), draw.background.a);
  vkCmdPushConstants(cmd, pipelines.layout(), VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(push), &push);
  vkCmdDraw(cmd, 3, 1, 0, 0);
  vkCmdEndRendering(cmd);
  return {};
}

}  // namespace pw::engine::gpu
