// Buffers and images with their memory, owned together. One allocation each: a
// scene has a handful of buffers and one image per texture, far below
// maxMemoryAllocationCount, so a sub-allocator would buy nothing yet.
#pragma once

#include <cstdint>

#include <vulkan/vulkan.h>

#include "base/result.h"
#include "engine/gpu/context.h"
#include "engine/gpu/vk_owner.h"

namespace pw::engine::gpu {

enum class MemoryUse {
  kDeviceLocal,  // written by transfers, read by the GPU
  kUpload,       // written by the CPU through `mapped` (staging, per-frame uniforms)
  kReadback,     // written by the GPU, read by the CPU through `mapped` (cached when possible)
};

struct Buffer {
  OwnedBuffer buffer;
  OwnedMemory memory;
  VkDeviceSize size = 0;
  void* mapped = nullptr;  // kUpload / kReadback: mapped for the buffer's life
  bool coherent = true;    // false: call invalidate() before reading `mapped`

  VkBuffer get() const { return buffer.get(); }
};

Result<Buffer> createBuffer(const Context& context, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use);

// Makes GPU writes to a kReadback buffer visible to the CPU (no-op when coherent).
Status invalidate(const Context& context, const Buffer& buffer);

struct ImageSpec {
  VkFormat format = VK_FORMAT_R8G8B8A8_SRGB;
  uint32_t width = 1;
  uint32_t height = 1;
  uint32_t mipLevels = 1;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  VkImageUsageFlags usage = 0;
  VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
  bool transient = false;  // multisampled targets that are only resolved: lazily allocated where possible
};

struct GpuImage {
  OwnedImage image;
  OwnedMemory memory;
  OwnedImageView view;  // all mip levels
  ImageSpec spec;

  VkImage get() const { return image.get(); }
};

Result<GpuImage> createImage(const Context& context, const ImageSpec& spec);

// The number of mip levels of a full chain down to 1x1.
uint32_t mipLevelCount(uint32_t width, uint32_t height);

// Whether the device can make `format`'s mip chain by linear blits (else textures
// get one level).
bool canBlitMips(const Context& context, VkFormat format);

// Fills the rest of the chain from level 0, which is in TRANSFER_DST_OPTIMAL after a
// copy, by halving blits (linear filtering in linear light for sRGB formats), leaving
// every level SHADER_READ_ONLY_OPTIMAL for the fragment shader.
void recordMipChain(VkCommandBuffer cmd, const GpuImage& image);

}  // namespace pw::engine::gpu
