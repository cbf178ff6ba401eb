// Uploads without waiting: each one's commands are submitted on the renderer's queue
// and the caller goes on; what the GPU still reads (the staging buffer) and writes
// (the new scene or image) is kept alive until the upload's fence signals. Frames
// submitted later see the upload's results: one queue runs them in submission order,
// and each upload ends with a barrier towards the stages that read what it wrote.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include <vulkan/vulkan.h>

#include "base/result.h"
#include "engine/gpu/context.h"
#include "engine/gpu/vk_owner.h"

namespace pw::engine::gpu {

class UploadQueue {
 public:
  explicit UploadQueue(const Context& context) : context_(context) {}
  // Waits for the uploads still running (teardown only: what they write goes next).
  ~UploadQueue();
  UploadQueue(const UploadQueue&) = delete;
  UploadQueue& operator=(const UploadQueue&) = delete;

  // Records `record` into a command buffer of its own and submits it; does not wait.
  // `keepAlive` lives until the GPU has finished the commands.
  Status submit(const std::function<void(VkCommandBuffer)>& record, std::shared_ptr<const void> keepAlive);

  // Frees the uploads that have finished; never waits. Called before each upload and
  // each frame.
  Status collect();

  // Waits for every upload still running (tests, benchmarks: the moment an upload is done).
  Status waitAll();

  size_t pending() const { return pending_.size(); }

 private:
  struct Pending {
    OwnedCommandPool commandPool;  // frees the command buffer with it
    OwnedFence fence;
    std::shared_ptr<const void> keepAlive;
  };
  const Context& context_;
  std::vector<Pending> pending_;
};

}  // namespace pw::engine::gpu
