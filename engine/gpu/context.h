// The Vulkan instance, the chosen device and its queue, and the validation messages.
// Internal to pw_gpu: Renderer owns one Context, everything else borrows it.
#pragma once

#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <type_traits>
#include <vector>

#include <vulkan/vulkan.h>

#include "base/result.h"
#include "engine/gpu/vk_owner.h"

namespace pw::engine::gpu {

// Validation-layer messages of severity warning or error, collected from the layer's
// callback (any thread).
class ValidationLog {
 public:
  void add(std::string message);
  size_t count() const;
  std::vector<std::string> messages() const;  // the first kKept of them
  static constexpr size_t kKept = 64;

 private:
  mutable std::mutex mutex_;
  size_t count_ = 0;
  std::vector<std::string> messages_;
};

struct ContextOptions {
  bool forceCpu = false;
  bool validation = false;
  bool validationRequired = false;  // true: a missing validation layer is an error, else a warning
  std::vector<std::string> instanceExtensions;  // e.g. GLFW's surface extensions
};

class Context {
 public:
  static Result<std::unique_ptr<Context>> create(const ContextOptions& options);
  ~Context() = default;
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  VkInstance instance() const { return instance_.get(); }
  VkPhysicalDevice physicalDevice() const { return physicalDevice_; }
  VkDevice device() const { return device_.get(); }
  VkQueue queue() const { return queue_; }
  uint32_t queueFamily() const { return queueFamily_; }
  const VkPhysicalDeviceProperties& properties() const { return properties_; }
  bool anisotropySupported() const { return anisotropy_; }
  bool swapchainSupported() const { return swapchain_; }
  // VK_KHR_swapchain_mutable_format, enabled where offered: a swapchain image can also
  // be viewed in another format of its class (the Presenter's UNORM overlay view).
  bool swapchainMutableFormatSupported() const { return swapchainMutableFormat_; }
  bool validationEnabled() const { return messenger_.handle != VK_NULL_HANDLE; }
  ValidationLog& validationLog() { return *log_; }
  const std::vector<std::string>& notes() const { return notes_; }  // e.g. "validation layer missing"

  // A memory type among `typeBits` with all of `required`, preferring one that also has `preferred`.
  Result<uint32_t> memoryType(uint32_t typeBits, VkMemoryPropertyFlags required,
                              VkMemoryPropertyFlags preferred = 0) const;

  // Commands recorded into a one-time command buffer of their own and submitted; the
  // buffer (freed with its pool) must live until the fence has signalled.
  struct Submission {
    OwnedCommandPool commandPool;
    OwnedFence fence;
  };
  // Records commands with `record` and submits them without waiting (upload_queue.h).
  Result<Submission> submit(const std::function<void(VkCommandBuffer)>& record) const;
  // The same, then waits for them.
  Status submitAndWait(const std::function<void(VkCommandBuffer)>& record) const;

 private:
  Context() = default;
  Status createInstance(const ContextOptions& options);
  Status pickPhysicalDevice(bool forceCpu);
  Status createDevice();

  struct InstanceDeleter {
    void operator()(VkInstance instance) const { vkDestroyInstance(instance, nullptr); }
  };
  struct DeviceDeleter {
    void operator()(VkDevice device) const { vkDestroyDevice(device, nullptr); }
  };
  struct MessengerOwner {
    VkInstance instance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT handle = VK_NULL_HANDLE;
    MessengerOwner() = default;
    MessengerOwner(const MessengerOwner&) = delete;
    MessengerOwner& operator=(const MessengerOwner&) = delete;
    ~MessengerOwner();
  };

  // Member order is teardown order, reversed: the device goes first, the log last.
  std::unique_ptr<ValidationLog> log_ = std::make_unique<ValidationLog>();
  std::vector<std::string> notes_;
  std::vector<std::string> enabledInstanceExtensions_;
  std::unique_ptr<std::remove_pointer_t<VkInstance>, InstanceDeleter> instance_;
  MessengerOwner messenger_;
  VkPhysicalDevice physicalDevice_ = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties properties_{};
  VkPhysicalDeviceMemoryProperties memoryProperties_{};
  std::unique_ptr<std::remove_pointer_t<VkDevice>, DeviceDeleter> device_;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queueFamily_ = 0;
  bool anisotropy_ = false;
  bool swapchain_ = false;
  bool swapchainMutableFormat_ = false;
};

}  // namespace pw::engine::gpu
