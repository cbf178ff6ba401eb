#include "engine/gpu/resources.h"

#include <algorithm>
#include <bit>

#include "engine/gpu/barriers.h"
#include "engine/gpu/vk_check.h"

namespace pw::engine::gpu {

Result<Buffer> createBuffer(const Context& context, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use) {
  const VkDevice device = context.device();
  Buffer out;
  out.size = std::max<VkDeviceSize>(size, 4);  // zero-sized buffers are invalid; empty scenes still bind one
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = out.size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkBuffer buffer = VK_NULL_HANDLE;
  PW_VK_CHECK(vkCreateBuffer(device, &info, nullptr, &buffer));
  out.buffer = OwnedBuffer(device, buffer);

  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(device, buffer, &req);
  Result<uint32_t> type = makeError("");
  switch (use) {
    case MemoryUse::kDeviceLocal:
      type = context.memoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
      if (!type) type = context.memoryType(req.memoryTypeBits, 0);
      break;
    case MemoryUse::kUpload:
      type = context.memoryType(req.memoryTypeBits,
                                VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
      break;
    case MemoryUse::kReadback:
      type = context.memoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT,
                                VK_MEMORY_PROPERTY_HOST_CACHED_BIT);
      break;
  }
  if (!type) return type.error();
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = *type;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  PW_VK_CHECK(vkAllocateMemory(device, &alloc, nullptr, &memory));
  out.memory = OwnedMemory(device, memory);
  PW_VK_CHECK(vkBindBufferMemory(device, buffer, memory, 0));
  if (use != MemoryUse::kDeviceLocal) {
    PW_VK_CHECK(vkMapMemory(device, memory, 0, VK_WHOLE_SIZE, 0, &out.mapped));
    VkPhysicalDeviceMemoryProperties props;
    vkGetPhysicalDeviceMemoryProperties(context.physicalDevice(), &props);
    out.coherent = props.memoryTypes[*type].propertyFlags & VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  }
  return out;
}

Status invalidate(const Context& context, const Buffer& buffer) {
  if (buffer.coherent) return {};
  VkMappedMemoryRange range{VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE};
  range.memory = buffer.memory.get();
  range.offset = 0;
  range.size = VK_WHOLE_SIZE;
  PW_VK_CHECK(vkInvalidateMappedMemoryRanges(context.device(), 1, &range));
  return {};
}

Result<GpuImage> createImage(const Context& context, const ImageSpec& spec) {
  const VkDevice device = context.device();
  GpuImage out;
  out.spec = spec;
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = spec.format;
  info.extent = {spec.width, spec.height, 1};
  info.mipLevels = spec.mipLevels;
  info.arrayLayers = 1;
  info.samples = spec.samples;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = spec.usage | (spec.transient ? VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT : 0);
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkImage image = VK_NULL_HANDLE;
  PW_VK_CHECK(vkCreateImage(device, &info, nullptr, &image));
  out.image = OwnedImage(device, image);

  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(device, image, &req);
  auto type = context.memoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT,
                                 spec.transient ? VK_MEMORY_PROPERTY_LAZILY_ALLOCATED_BIT : 0);
  if (!type) type = context.memoryType(req.memoryTypeBits, 0);
  if (!type) return type.error();
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = *type;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  PW_VK_CHECK(vkAllocateMemory(device, &alloc, nullptr, &memory));
  out.memory = OwnedMemory(device, memory);
  PW_VK_CHECK(vkBindImageMemory(device, image, memory, 0));

  VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  viewInfo.image = image;
  viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
  viewInfo.format = spec.format;
  viewInfo.subresourceRange = {spec.aspect, 0, spec.mipLevels, 0, 1};
  VkImageView view = VK_NULL_HANDLE;
  PW_VK_CHECK(vkCreateImageView(device, &viewInfo, nullptr, &view));
  out.view = OwnedImageView(device, view);
  return out;
}

uint32_t mipLevelCount(uint32_t width, uint32_t height) {
  return static_cast<uint32_t>(std::bit_width(std::max(width, height)));
}

bool canBlitMips(const Context& context, VkFormat format) {
  VkFormatProperties props;
  vkGetPhysicalDeviceFormatProperties(context.physicalDevice(), format, &props);
  const VkFormatFeatureFlags needed = VK_FORMAT_FEATURE_BLIT_SRC_BIT | VK_FORMAT_FEATURE_BLIT_DST_BIT |
                                      VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
  return (props.optimalTilingFeatures & needed) == needed;
}

void recordMipChain(VkCommandBuffer cmd, const GpuImage& image) {
  const uint32_t levels = image.spec.mipLevels;
  int32_t w = static_cast<int32_t>(image.spec.width), h = static_cast<int32_t>(image.spec.height);
  for (uint32_t level = 1; level < levels; ++level) {
    transitionImage(cmd, {image.get(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                          VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_READ_BIT, VK_IMAGE_ASPECT_COLOR_BIT, level - 1, 1});
    const int32_t nw = std::max(w / 2, 1), nh = std::max(h / 2, 1);
    VkImageBlit blit{};
    blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level - 1, 0, 1};
    blit.srcOffsets[1] = {w, h, 1};
    blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, 1};
    blit.dstOffsets[1] = {nw, nh, 1};
    vkCmdBlitImage(cmd, image.get(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image.get(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                   1, &blit, VK_FILTER_LINEAR);
    w = nw;
    h = nh;
  }
  const ImageTransition done[2] = {
      {image.get(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
       VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
       VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, VK_IMAGE_ASPECT_COLOR_BIT, 0, levels - 1},
      {image.get(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
       VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
       VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, VK_IMAGE_ASPECT_COLOR_BIT,
       levels - 1, 1},
  };
  if (levels > 1) {
    transitionImages(cmd, done);
  } else {
    transitionImage(cmd, done[1]);
  }
}

}  // namespace pw::engine::gpu
