#include "engine/gpu/frame_slot.h"

#include <algorithm>

#include "engine/gpu/vk_check.h"

namespace pw::engine::gpu {
namespace {

constexpr uint32_t kInitialViews = 4;  // scene views per frame before the uniform buffer grows

}  // namespace

Status FrameSlot::waitAndReset(VkDevice device) {
  const VkFence handle = fence.get();
  PW_VK_CHECK(vkWaitForFences(device, 1, &handle, VK_TRUE, UINT64_MAX));
  inFlight.clear();
  PW_VK_CHECK(vkResetCommandPool(device, commandPool.get(), 0));
  return {};
}

Status FrameSlot::reserveViews(const Context& context, uint32_t views) {
  if (views <= viewCapacity) return {};
  const VkDeviceSize alignment = std::max<VkDeviceSize>(context.properties().limits.minUniformBufferOffsetAlignment, 16);
  const VkDeviceSize stride = (sizeof(FrameUniforms) + alignment - 1) / alignment * alignment;
  const uint32_t capacity = std::max(views, viewCapacity * 2);
  auto buffer = createBuffer(context, stride * capacity, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, MemoryUse::kUpload);
  if (!buffer) return buffer.error();
  uniforms = std::move(*buffer);
  uniformStride = stride;
  viewCapacity = capacity;
  // One FrameUniforms is visible through the descriptor; the dynamic offset picks which.
  const VkDescriptorBufferInfo bufferInfo{uniforms.get(), 0, sizeof(FrameUniforms)};
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.dstSet = frameSet;
  write.dstBinding = PW_BINDING_FRAME_UNIFORMS;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC;
  write.pBufferInfo = &bufferInfo;
  vkUpdateDescriptorSets(context.device(), 1, &write, 0, nullptr);
  return {};
}

Result<OwnedDescriptorPool> createFrameDescriptorPool(const Context& context, uint32_t count) {
  const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, count};
  VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  info.maxSets = count;
  info.poolSizeCount = 1;
  info.pPoolSizes = &size;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  PW_VK_CHECK(vkCreateDescriptorPool(context.device(), &info, nullptr, &pool));
  return OwnedDescriptorPool(context.device(), pool);
}

Result<FrameSlot> createFrameSlot(const Context& context, const PipelineLibrary& pipelines, VkDescriptorPool pool) {
  const VkDevice device = context.device();
  FrameSlot slot;
  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
  poolInfo.queueFamilyIndex = context.queueFamily();
  VkCommandPool commandPool = VK_NULL_HANDLE;
  PW_VK_CHECK(vkCreateCommandPool(device, &poolInfo, nullptr, &commandPool));
  slot.commandPool = OwnedCommandPool(device, commandPool);

  VkCommandBufferAllocateInfo allocInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  allocInfo.commandPool = commandPool;
  allocInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocInfo.commandBufferCount = 1;
  PW_VK_CHECK(vkAllocateCommandBuffers(device, &allocInfo, &slot.commands));

  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  fenceInfo.flags = VK_FENCE_CREATE_SIGNALED_BIT;
  VkFence fence = VK_NULL_HANDLE;
  PW_VK_CHECK(vkCreateFence(device, &fenceInfo, nullptr, &fence));
  slot.fence = OwnedFence(device, fence);

  const VkDescriptorSetLayout layout = pipelines.frameSetLayout();
  VkDescriptorSetAllocateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  setInfo.descriptorPool = pool;
  setInfo.descriptorSetCount = 1;
  setInfo.pSetLayouts = &layout;
  PW_VK_CHECK(vkAllocateDescriptorSets(device, &setInfo, &slot.frameSet));
  PW_TRY(slot.reserveViews(context, kInitialViews));
  return slot;
}

}  // namespace pw::engine::gpu
