// Small helpers for synchronization2 barriers (images: one subresource range each).
#pragma once

#include <vulkan/vulkan.h>

namespace pw::engine::gpu {

struct ImageTransition {
  VkImage image = VK_NULL_HANDLE;
  VkImageLayout oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkImageLayout newLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkPipelineStageFlags2 srcStage = VK_PIPELINE_STAGE_2_NONE;
  VkAccessFlags2 srcAccess = VK_ACCESS_2_NONE;
  VkPipelineStageFlags2 dstStage = VK_PIPELINE_STAGE_2_NONE;
  VkAccessFlags2 dstAccess = VK_ACCESS_2_NONE;
  VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
  uint32_t baseMip = 0;
  uint32_t mipCount = VK_REMAINING_MIP_LEVELS;
};

inline VkImageMemoryBarrier2 toBarrier(const ImageTransition& t) {
  VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
  b.srcStageMask = t.srcStage;
  b.srcAccessMask = t.srcAccess;
  b.dstStageMask = t.dstStage;
  b.dstAccessMask = t.dstAccess;
  b.oldLayout = t.oldLayout;
  b.newLayout = t.newLayout;
  b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = t.image;
  b.subresourceRange = {t.aspect, t.baseMip, t.mipCount, 0, 1};
  return b;
}

// Records the transitions as one vkCmdPipelineBarrier2.
template <size_t N>
void transitionImages(VkCommandBuffer cmd, const ImageTransition (&transitions)[N]) {
  VkImageMemoryBarrier2 barriers[N];
  for (size_t i = 0; i < N; ++i) barriers[i] = toBarrier(transitions[i]);
  VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dependency.imageMemoryBarrierCount = static_cast<uint32_t>(N);
  dependency.pImageMemoryBarriers = barriers;
  vkCmdPipelineBarrier2(cmd, &dependency);
}

inline void transitionImage(VkCommandBuffer cmd, const ImageTransition& transition) {
  const ImageTransition one[1] = {transition};
  transitionImages(cmd, one);
}

// Makes what a copy wrote into `buffer` visible to the host (read-backs).
inline void copyToHostBarrier(VkCommandBuffer cmd, VkBuffer buffer) {
  VkBufferMemoryBarrier2 toHost{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
  toHost.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
  toHost.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
  toHost.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
  toHost.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
  toHost.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  toHost.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  toHost.buffer = buffer;
  toHost.size = VK_WHOLE_SIZE;
  VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dependency.bufferMemoryBarrierCount = 1;
  dependency.pBufferMemoryBarriers = &toHost;
  vkCmdPipelineBarrier2(cmd, &dependency);
}

}  // namespace pw::engine::gpu
