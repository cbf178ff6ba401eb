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
  auto submission = context_.submit(record);
  if (!submission) return submission.error();
  pending_.push_back({std::move(submission->commandPool), std::move(submission->fence), std::move(keepAlive)});
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
