#include "engine/gpu/view_image.h"

#include <cstring>

#include "engine/gpu/barriers.h"
#include "engine/gpu/pipelines.h"
#include "engine/gpu/vk_check.h"

namespace pw::engine::gpu {
namespace {

// The two descriptor sets (trilinear and nearest) for `image`'s colour image.
Status describe(const Context& context, const ImagePipelines& pipelines, ViewImage& image) {
  const VkDevice device = context.device();
  const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 2};
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.maxSets = 2;
  poolInfo.poolSizeCount = 1;
  poolInfo.pPoolSizes = &size;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  PW_VK_CHECK(vkCreateDescriptorPool(device, &poolInfo, nullptr, &pool));
  image.descriptorPool = OwnedDescriptorPool(device, pool);
  const VkDescriptorSetLayout layouts[2] = {pipelines.setLayout(), pipelines.setLayout()};
  VkDescriptorSetAllocateInfo allocInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  allocInfo.descriptorPool = pool;
  allocInfo.descriptorSetCount = 2;
  allocInfo.pSetLayouts = layouts;
  VkDescriptorSet sets[2];
  PW_VK_CHECK(vkAllocateDescriptorSets(device, &allocInfo, sets));
  image.smoothSet = sets[0];
  image.nearestSet = sets[1];
  const VkDescriptorImageInfo infos[2] = {
      {pipelines.sampler(ImageFilter::kSmooth), image.color.view.get(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
      {pipelines.sampler(ImageFilter::kNearest), image.color.view.get(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
  };
  VkWriteDescriptorSet writes[2];
  for (int i = 0; i < 2; ++i) {
    writes[i] = VkWriteDescriptorSet{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    writes[i].dstSet = sets[i];
    writes[i].dstBinding = PW_BINDING_IMAGE;
    writes[i].descriptorCount = 1;
    writes[i].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    writes[i].pImageInfo = &infos[i];
  }
  vkUpdateDescriptorSets(device, 2, writes, 0, nullptr);
  return {};
}

Status checkSize(const Context& context, int64_t width, int64_t height, const char* what) {
  const int64_t maxSide = context.properties().limits.maxImageDimension2D;
  if (width < 1 || height < 1 || width > maxSide || height > maxSide) {
    return makeError(std::string(what) + " of " + std::to_string(width) + "x" + std::to_string(height) +
                     " pixels cannot be made: each side must be 1.." + std::to_string(maxSide) + " on " +
                     context.properties().deviceName + (width > maxSide || height > maxSide ? "; scale it down" : ""));
  }
  return {};
}

}  // namespace

Result<std::shared_ptr<const ViewImage>> ViewImage::upload(const Context& context, const ImagePipelines& pipelines,
                                                           const Image& image, UploadQueue& uploads) {
  PW_TRY(checkSize(context, image.width, image.height, "an image"));
  const VkDeviceSize bytes = VkDeviceSize(image.width) * VkDeviceSize(image.height) * 4;
  if (image.rgba.size() != bytes) {
    return makeError("an image of " + std::to_string(image.width) + "x" + std::to_string(image.height) + " pixels has " +
                     std::to_string(image.rgba.size()) + " bytes of RGBA, not " + std::to_string(bytes));
  }
  auto out = std::make_shared<ViewImage>();
  ImageSpec spec;
  spec.format = kViewImageFormat;
  spec.width = static_cast<uint32_t>(image.width);
  spec.height = static_cast<uint32_t>(image.height);
  spec.mipLevels = canBlitMips(context, kViewImageFormat) ? mipLevelCount(spec.width, spec.height) : 1;
  spec.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  auto color = createImage(context, spec);
  if (!color) return color.error();
  out->color = std::move(*color);

  auto stagingBuffer = createBuffer(context, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::kUpload);
  if (!stagingBuffer) return stagingBuffer.error();
  const auto staging = std::make_shared<const Buffer>(std::move(*stagingBuffer));
  std::memcpy(staging->mapped, image.rgba.data(), bytes);
  out->opaque = true;
  for (size_t i = 3; i < image.rgba.size() && out->opaque; i += 4) out->opaque = image.rgba[i] == 255;
  PW_TRY(describe(context, pipelines, *out));

  const auto keepAlive = std::make_shared<std::pair<std::shared_ptr<const Buffer>, std::shared_ptr<const ViewImage>>>(
      staging, out);
  PW_TRY(uploads.submit(
      [&](VkCommandBuffer cmd) {
        transitionImage(cmd, {out->color.get(), VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                              VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE,
                              VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT});
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {spec.width, spec.height, 1};
        vkCmdCopyBufferToImage(cmd, staging->get(), out->color.get(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        recordMipChain(cmd, out->color);  // ends with every level readable by fragment shaders
      },
      keepAlive));
  return std::shared_ptr<const ViewImage>(std::move(out));
}

Result<std::shared_ptr<const ViewImage>> ViewImage::renderTarget(const Context& context, const ImagePipelines& pipelines,
                                                                 uint32_t width, uint32_t height,
                                                                 VkSampleCountFlagBits samples, UploadQueue& uploads) {
  PW_TRY(checkSize(context, width, height, "a render target"));
  auto out = std::make_shared<ViewImage>();
  ImageSpec spec;
  spec.format = kViewImageFormat;
  spec.width = width;
  spec.height = height;
  spec.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
               VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  auto color = createImage(context, spec);
  if (!color) return color.error();
  out->color = std::move(*color);
  ImageSpec msaaSpec = spec;
  msaaSpec.samples = samples;
  msaaSpec.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
  msaaSpec.transient = true;
  if (samples != VK_SAMPLE_COUNT_1_BIT) {
    auto msaa = createImage(context, msaaSpec);
    if (!msaa) return msaa.error();
    out->msaa = std::move(*msaa);
  }
  ImageSpec depthSpec = msaaSpec;
  depthSpec.format = kDepthFormat;
  depthSpec.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
  depthSpec.aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
  auto depth = createImage(context, depthSpec);
  if (!depth) return depth.error();
  out->depth = std::move(*depth);
  PW_TRY(describe(context, pipelines, *out));

  PW_TRY(uploads.submit(
      [&](VkCommandBuffer cmd) {
        const VkImage image = out->color.get();
        transitionImage(cmd, {image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                              VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_CLEAR_BIT,
                              VK_ACCESS_2_TRANSFER_WRITE_BIT});
        const VkClearColorValue transparent{{0.0f, 0.0f, 0.0f, 0.0f}};
        const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        vkCmdClearColorImage(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &transparent, 1, &range);
        transitionImage(cmd, {image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                              VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                              VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                              VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT});
      },
      out));
  return std::shared_ptr<const ViewImage>(std::move(out));
}

}  // namespace pw::engine::gpu
