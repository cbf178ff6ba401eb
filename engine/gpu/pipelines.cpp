#include "engine/gpu/pipelines.h"

#include <algorithm>

#include "engine/gpu/vk_check.h"
#include "shaders/spirv.h"

namespace pw::engine::gpu {

Result<OwnedDescriptorSetLayout> makeSetLayout(VkDevice device, std::initializer_list<VkDescriptorSetLayoutBinding> bindings) {
  VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  info.bindingCount = static_cast<uint32_t>(bindings.size());
  info.pBindings = bindings.begin();
  VkDescriptorSetLayout layout = VK_NULL_HANDLE;
  PW_VK_CHECK(vkCreateDescriptorSetLayout(device, &info, nullptr, &layout));
  return OwnedDescriptorSetLayout(device, layout);
}

Result<OwnedShaderModule> makeShader(VkDevice device, std::span<const uint32_t> words) {
  VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  info.codeSize = words.size_bytes();
  info.pCode = words.data();
  VkShaderModule module = VK_NULL_HANDLE;
  PW_VK_CHECK(vkCreateShaderModule(device, &info, nullptr, &module));
  return OwnedShaderModule(device, module);
}

Result<OwnedPipelineLayout> makePipelineLayout(VkDevice device, std::span<const VkDescriptorSetLayout> sets,
                                               const VkPushConstantRange& push) {
  VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  info.setLayoutCount = static_cast<uint32_t>(sets.size());
  info.pSetLayouts = sets.data();
  info.pushConstantRangeCount = 1;
  info.pPushConstantRanges = &push;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  PW_VK_CHECK(vkCreatePipelineLayout(device, &info, nullptr, &layout));
  return OwnedPipelineLayout(device, layout);
}

namespace {

bool isSrgbFormat(VkFormat f) {
  return f == VK_FORMAT_R8G8B8A8_SRGB || f == VK_FORMAT_B8G8R8A8_SRGB || f == VK_FORMAT_A8B8G8R8_SRGB_PACK32;
}

constexpr VkShaderStageFlags kGraphicsStages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

}  // namespace

Result<std::unique_ptr<PipelineLibrary>> PipelineLibrary::create(const Context& context, bool anisotropic,
                                                                  bool vertexLighting) {
  const VkDevice device = context.device();
  std::unique_ptr<PipelineLibrary> lib(new PipelineLibrary(context));
  {
    auto frame = makeSetLayout(device, {{PW_BINDING_FRAME_UNIFORMS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, 1, kGraphicsStages, nullptr}});
    if (!frame) return frame.error();
    lib->frameSetLayout_ = std::move(*frame);
    auto scene = makeSetLayout(device, {{PW_BINDING_LIGHTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, kGraphicsStages, nullptr},
                                        {PW_BINDING_SHAPES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT, nullptr},
                                        {PW_BINDING_LIGHT_LISTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, kGraphicsStages, nullptr}});
    if (!scene) return scene.error();
    lib->sceneSetLayout_ = std::move(*scene);
    auto texture = makeSetLayout(device, {{PW_BINDING_TEXTURE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr}});
    if (!texture) return texture.error();
    lib->textureSetLayout_ = std::move(*texture);
  }
  static_assert(PW_SET_FRAME == 0 && PW_SET_SCENE == 1 && PW_SET_TEXTURE == 2, "set order below");
  const VkDescriptorSetLayout sets[] = {lib->frameSetLayout(), lib->sceneSetLayout(), lib->textureSetLayout()};
  const VkPushConstantRange push{kGraphicsStages, 0, sizeof(DrawPushConstants)};
  auto layout = makePipelineLayout(device, sets, push);
  if (!layout) return layout.error();
  lib->layout_ = std::move(*layout);

  auto vert = makeShader(device, shaders::sceneVertSpirv());
  if (!vert) return vert.error();
  lib->vertexShader_ = std::move(*vert);
  auto frag = makeShader(device, shaders::sceneFragSpirv());
  if (!frag) return frag.error();
  lib->fragmentShader_ = std::move(*frag);

  lib->anisotropic_ = anisotropic && context.anisotropySupported();
  lib->vertexLighting_ = vertexLighting;
  lib->cpuDevice_ = context.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  for (int i = 0; i < 8; ++i) {
    const bool anisotropicSampler = lib->anisotropic_ && i >= 4;
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = VK_FILTER_LINEAR;
    info.minFilter = VK_FILTER_LINEAR;
    info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
    info.addressModeU = (i & 1) ? VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE : VK_SAMPLER_ADDRESS_MODE_REPEAT;
    info.addressModeV = (i & 2) ? VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE : VK_SAMPLER_ADDRESS_MODE_REPEAT;
    info.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    info.anisotropyEnable = anisotropicSampler ? VK_TRUE : VK_FALSE;
    info.maxAnisotropy = anisotropicSampler ? std::min(16.0f, context.properties().limits.maxSamplerAnisotropy) : 1.0f;
    info.minLod = 0.0f;
    info.maxLod = VK_LOD_CLAMP_NONE;
    VkSampler sampler = VK_NULL_HANDLE;
    PW_VK_CHECK(vkCreateSampler(device, &info, nullptr, &sampler));
    lib->samplers_[i] = OwnedSampler(device, sampler);
  }
  return lib;
}

Result<VkPipeline> PipelineLibrary::pipeline(VkFormat format, VkSampleCountFlagBits samples, PipelineVariant variant) {
  const auto key = std::tuple(format, samples, variant.index());
  if (auto found = pipelines_.find(key); found != pipelines_.end()) return found->second.get();

  // The fragment shader's specialization (shader_interface.h, PW_SPEC_*).
  const VkBool32 constants[5] = {variant.textured ? VK_TRUE : VK_FALSE, variant.lit ? VK_TRUE : VK_FALSE,
                                 isSrgbFormat(format) ? VK_FALSE : VK_TRUE, variant.photoTexture ? VK_TRUE : VK_FALSE,
                                 vertexLighting_ ? VK_TRUE : VK_FALSE};
  static_assert(PW_SPEC_TEXTURED == 0 && PW_SPEC_LIT == 1 && PW_SPEC_ENCODE_SRGB == 2 && PW_SPEC_PHOTO_TEXTURE == 3 &&
                    PW_SPEC_VERTEX_LIGHTING == 4,
                "order of `constants`");
  VkSpecializationMapEntry entries[5];
  for (uint32_t i = 0; i < 5; ++i) entries[i] = {i, i * uint32_t(sizeof(VkBool32)), sizeof(VkBool32)};
  // Both stages get every constant; each reads the ones it declares.
  const VkSpecializationInfo specialization{5, entries, sizeof(constants), constants};
  const VkPipelineShaderStageCreateInfo stages[] = {
      {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, VK_SHADER_STAGE_VERTEX_BIT, vertexShader_.get(), "main", &specialization},
      {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, VK_SHADER_STAGE_FRAGMENT_BIT, fragmentShader_.get(), "main", &specialization},
  };
  const VkVertexInputBindingDescription binding{0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX};
  const VkVertexInputAttributeDescription attributes[] = {
      {PW_LOCATION_POSITION, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, position)},
      {PW_LOCATION_NORMAL, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, normal)},
      {PW_LOCATION_TEXCOORD, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(Vertex, texCoord)},
      {PW_LOCATION_COLOR, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(Vertex, color)},
  };
  VkPipelineVertexInputStateCreateInfo vertexInput{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  vertexInput.vertexBindingDescriptionCount = 1;
  vertexInput.pVertexBindingDescriptions = &binding;
  vertexInput.vertexAttributeDescriptionCount = 4;
  vertexInput.pVertexAttributeDescriptions = attributes;

  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = variant.topology == Topology::kTriangles ? VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST
                      : variant.topology == Topology::kLines   ? VK_PRIMITIVE_TOPOLOGY_LINE_LIST
                                                               : VK_PRIMITIVE_TOPOLOGY_POINT_LIST;

  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.lineWidth = 1.0f;
  // cullMode and frontFace are dynamic: solid FALSE shapes and mirrored transforms
  // share the pipeline of their variant.

  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = samples;

  VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = VK_TRUE;
  depth.depthWriteEnable = variant.blended ? VK_FALSE : VK_TRUE;  // transparent surfaces do not hide what is behind
  depth.depthCompareOp = VK_COMPARE_OP_LESS_OR_EQUAL;

  VkPipelineColorBlendAttachmentState blend{};
  blend.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  if (variant.blended) {
    blend.blendEnable = VK_TRUE;
    blend.srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
    blend.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    blend.colorBlendOp = VK_BLEND_OP_ADD;
    // The frame stays opaque (alpha 1 from the clear) so the PNG has no holes.
    blend.srcAlphaBlendFactor = VK_BLEND_FACTOR_ZERO;
    blend.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
    blend.alphaBlendOp = VK_BLEND_OP_ADD;
  } else {
    blend.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT;
  }
  VkPipelineColorBlendStateCreateInfo blendState{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  blendState.attachmentCount = 1;
  blendState.pAttachments = &blend;

  const VkDynamicState dynamics[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR, VK_DYNAMIC_STATE_CULL_MODE,
                                     VK_DYNAMIC_STATE_FRONT_FACE};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dynamic.dynamicStateCount = 4;
  dynamic.pDynamicStates = dynamics;

  auto pipeline = createGraphicsPipeline(context_.device(), {stages, &vertexInput, &assembly, &raster, &multisample, &depth,
                                                            &blendState, &dynamic, layout_.get(), format, kDepthFormat});
  if (!pipeline) return pipeline.error();
  return pipelines_.emplace(key, std::move(*pipeline)).first->second.get();
}

Result<OwnedPipeline> createGraphicsPipeline(VkDevice device, const GraphicsPipelineParts& parts) {
  VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
  rendering.colorAttachmentCount = 1;
  rendering.pColorAttachmentFormats = &parts.colorFormat;
  rendering.depthAttachmentFormat = parts.depthFormat;
  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;

  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  info.pNext = &rendering;
  info.stageCount = 2;
  info.pStages = parts.stages;
  info.pVertexInputState = parts.vertexInput;
  info.pInputAssemblyState = parts.assembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = parts.raster;
  info.pMultisampleState = parts.multisample;
  info.pDepthStencilState = parts.depth;
  info.pColorBlendState = parts.blend;
  info.pDynamicState = parts.dynamic;
  info.layout = parts.layout;
  VkPipeline pipeline = VK_NULL_HANDLE;
  PW_VK_CHECK(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
  return OwnedPipeline(device, pipeline);
}

}  // namespace pw::engine::gpu
