// What one frame in flight owns: its command buffer, the fence its submission
// signals, its uniform buffer (one FrameUniforms per scene view, each at its own
// dynamic offset) and descriptor set, and the deletion queue of objects its commands
// use (scenes and images above all), released once its fence has signalled.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <vulkan/vulkan.h>

#include "base/result.h"
#include "engine/gpu/context.h"
#include "engine/gpu/pipelines.h"
#include "engine/gpu/resources.h"
#include "engine/gpu/vk_owner.h"

namespace pw::engine::gpu {

struct FrameSlot {
  OwnedCommandPool commandPool;
  VkCommandBuffer commands = VK_NULL_HANDLE;
  OwnedFence fence;      // created signalled: a slot never used waits for nothing
  Buffer uniforms;       // viewCapacity FrameUniforms, uniformStride bytes apart, host-visible and mapped
  uint32_t viewCapacity = 0;
  VkDeviceSize uniformStride = 0;  // sizeof(FrameUniforms) rounded up to the device's offset alignment
  VkDescriptorSet frameSet = VK_NULL_HANDLE;  // from the owner's pool; a dynamic uniform buffer
  std::vector<std::shared_ptr<const void>> inFlight;

  // Waits for the slot's last submission, frees what it kept alive and resets the
  // command pool for recording.
  Status waitAndReset(VkDevice device);

  // Makes room for `views` scene views' uniforms (after waitAndReset: the buffer may be
  // replaced and the descriptor rewritten). Grows by doubling; never shrinks.
  Status reserveViews(const Context& context, uint32_t views);

  // Where scene view `index`'s FrameUniforms go, and its dynamic offset.
  void* uniformsFor(uint32_t index) const { return static_cast<uint8_t*>(uniforms.mapped) + index * uniformStride; }
  uint32_t dynamicOffset(uint32_t index) const { return static_cast<uint32_t>(index * uniformStride); }
};

// A descriptor pool with room for `count` frame sets.
Result<OwnedDescriptorPool> createFrameDescriptorPool(const Context& context, uint32_t count);
Result<FrameSlot> createFrameSlot(const Context& context, const PipelineLibrary& pipelines, VkDescriptorPool pool);

}  // namespace pw::engine::gpu
