// Move-only owners of Vulkan objects. The destructor frees the object; teardown
// order is member order, so a class declares what it owns after what that depends on
// (device first, then pools, then what comes from them).
#pragma once

#include <utility>

#include <vulkan/vulkan.h>

namespace pw::engine::gpu {

// An object created from a VkDevice and destroyed with vkDestroyX(device, handle, nullptr).
template <class Handle, auto kDestroy>
class DeviceOwned {
 public:
  DeviceOwned() = default;
  DeviceOwned(VkDevice device, Handle handle) : device_(device), handle_(handle) {}
  DeviceOwned(DeviceOwned&& other) noexcept
      : device_(other.device_), handle_(std::exchange(other.handle_, VK_NULL_HANDLE)) {}
  DeviceOwned& operator=(DeviceOwned&& other) noexcept {
    if (this != &other) {
      reset();
      device_ = other.device_;
      handle_ = std::exchange(other.handle_, VK_NULL_HANDLE);
    }
    return *this;
  }
  DeviceOwned(const DeviceOwned&) = delete;
  DeviceOwned& operator=(const DeviceOwned&) = delete;
  ~DeviceOwned() { reset(); }

  void reset() {
    if (handle_ != VK_NULL_HANDLE) kDestroy(device_, handle_, nullptr);
    handle_ = VK_NULL_HANDLE;
  }
  Handle get() const { return handle_; }
  explicit operator bool() const { return handle_ != VK_NULL_HANDLE; }

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  Handle handle_ = VK_NULL_HANDLE;
};

using OwnedBuffer = DeviceOwned<VkBuffer, vkDestroyBuffer>;
using OwnedImage = DeviceOwned<VkImage, vkDestroyImage>;
using OwnedImageView = DeviceOwned<VkImageView, vkDestroyImageView>;
using OwnedMemory = DeviceOwned<VkDeviceMemory, vkFreeMemory>;
using OwnedSampler = DeviceOwned<VkSampler, vkDestroySampler>;
using OwnedShaderModule = DeviceOwned<VkShaderModule, vkDestroyShaderModule>;
using OwnedPipeline = DeviceOwned<VkPipeline, vkDestroyPipeline>;
using OwnedPipelineLayout = DeviceOwned<VkPipelineLayout, vkDestroyPipelineLayout>;
using OwnedDescriptorSetLayout = DeviceOwned<VkDescriptorSetLayout, vkDestroyDescriptorSetLayout>;
using OwnedDescriptorPool = DeviceOwned<VkDescriptorPool, vkDestroyDescriptorPool>;
using OwnedCommandPool = DeviceOwned<VkCommandPool, vkDestroyCommandPool>;
using OwnedFence = DeviceOwned<VkFence, vkDestroyFence>;
using OwnedSemaphore = DeviceOwned<VkSemaphore, vkDestroySemaphore>;
using OwnedRenderPass = DeviceOwned<VkRenderPass, vkDestroyRenderPass>;
using OwnedFramebuffer = DeviceOwned<VkFramebuffer, vkDestroyFramebuffer>;
using OwnedSwapchain = DeviceOwned<VkSwapchainKHR, vkDestroySwapchainKHR>;

}  // namespace pw::engine::gpu
