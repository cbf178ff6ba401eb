#include "engine/gpu/upload_queue.h"

#include <algorithm>

#include "engine/gpu/vk_check.h"

namespace pw::engine::gpu {

UploadQueue::~UploadQueue() {
  for (const Pending& p : pending_) {
    const VkFence fence = p.fence.get();
    vkWaitForFences(context_.device(), 1, &fence, VK_TRUE, UINT64_MAX);
  }
}

Status UploadQueue::submit(const std::function<void(VkCommandBuffer)>& record, std::shared_ptr<const void> keepAlive) {
  const VkDevice device = context_.device();
  Pending p;
  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
  poolInfo.queueFamilyIndex = context_.queueFamily();
  VkCommandPool pool = VK_NULL_HANDLE;
  PW_VK_CHECK(vkCreateCommandPool(device, &poolInfo, nullptr, &pool));
  p.commandPool = OwnedCommandPool(device, pool);
  VkCommandBufferAllocateInfo allocInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  allocInfo.commandPool = pool;
  allocInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocInfo.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  PW_VK_CHECK(vkAllocateCommandBuffers(device, &allocInfo, &cmd));
  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VkFence fence = VK_NULL_HANDLE;
  PW_VK_CHECK(vkCreateFence(device, &fenceInfo, nullptr, &fence));
  p.fence = OwnedFence(device, fence);

  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  PW_VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
  record(cmd);
  PW_VK_CHECK(vkEndCommandBuffer(cmd));
  VkCommandBufferSubmitInfo cmdInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
  cmdInfo.commandBuffer = cmd;
  VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
  submit.commandBufferInfoCount = 1;
  submit.pCommandBufferInfos = &cmdInfo;
  PW_VK_CHECK(vkQueueSubmit2(context_.queue(), 1, &submit, fence));
  p.keepAlive = std::move(keepAlive);
  pending_.push_back(std::move(p));
  return {};
}

Status UploadQueue::collect() {
  const VkDevice device = context_.device();
  Status status;
  std::erase_if(pending_, [&](const Pending& p) {
    const VkResult r = vkGetFenceStatus(device, p.fence.get());
    if (r < 0 && status) status = vkCallError(__FILE__, __LINE__, "vkGetFenceStatus", r);
    return r == VK_SUCCESS;
  });
  return status;
}

Status UploadQueue::waitAll() {
  for (const Pending& p : pending_) {
    const VkFence fence = p.fence.get();
    PW_VK_CHECK(vkWaitForFences(context_.device(), 1, &fence, VK_TRUE, UINT64_MAX));
  }
  pending_.clear();
  return {};
}

}  // namespace pw::engine::gpu
