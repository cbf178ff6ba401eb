// What one frame in flight owns: its command buffer, the fence its submission
// signals, its uniform buffer and descriptor set, and the deletion queue of objects
// its commands use (the scene above all), released once its fence has signalled.
#pragma once

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
  Buffer uniforms;       // FrameUniforms, host-visible and mapped
  VkDescriptorSet frameSet = VK_NULL_HANDLE;  // from the owner's pool
  std::vector<std::shared_ptr<const void>> inFlight;

  // Waits for the slot's last submission, frees what it kept alive and resets the
  // command pool for recording.
  Status waitAndReset(VkDevice device);
};

// A descriptor pool with room for `count` frame sets.
Result<OwnedDescriptorPool> createFrameDescriptorPool(const Context& context, uint32_t count);
Result<FrameSlot> createFrameSlot(const Context& context, const PipelineLibrary& pipelines, VkDescriptorPool pool);

}  // namespace pw::engine::gpu
