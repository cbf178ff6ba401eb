#include "engine/gpu/context.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

#include "engine/gpu/device_select.h"
#include "engine/gpu/vk_check.h"
#include "engine/gpu/vk_owner.h"

namespace pw::engine::gpu {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

VKAPI_ATTR VkBool32 VKAPI_CALL onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  if (severity & (VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT)) {
    const char* text = data && data->pMessage ? data->pMessage : "(no message)";
    std::fprintf(stderr, "vulkan validation: %s\n", text);
    static_cast<ValidationLog*>(user)->add(text);
  }
  return VK_FALSE;  // never abort the call: the test that sees the count fails instead
}

bool hasLayer(const char* name) {
  uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  return std::any_of(layers.begin(), layers.end(), [&](const auto& l) { return !std::strcmp(l.layerName, name); });
}

std::vector<std::string> instanceExtensionNames(const char* layer) {
  uint32_t count = 0;
  vkEnumerateInstanceExtensionProperties(layer, &count, nullptr);
  std::vector<VkExtensionProperties> props(count);
  vkEnumerateInstanceExtensionProperties(layer, &count, props.data());
  std::vector<std::string> names;
  for (const auto& p : props) names.emplace_back(p.extensionName);
  return names;
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

void ValidationLog::add(std::string message) {
  std::lock_guard lock(mutex_);
  ++count_;
  if (messages_.size() < kKept) messages_.push_back(std::move(message));
}

size_t ValidationLog::count() const {
  std::lock_guard lock(mutex_);
  return count_;
}

std::vector<std::string> ValidationLog::messages() const {
  std::lock_guard lock(mutex_);
  return messages_;
}

Context::MessengerOwner::~MessengerOwner() {
  if (handle == VK_NULL_HANDLE) return;
  auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
  if (destroy) destroy(instance, handle, nullptr);
}

Result<std::unique_ptr<Context>> Context::create(const ContextOptions& options) {
  std::unique_ptr<Context> context(new Context());
  PW_TRY(context->createInstance(options));
  PW_TRY(context->pickPhysicalDevice(options.forceCpu));
  PW_TRY(context->createDevice());
  return context;
}

Status Context::createInstance(const ContextOptions& options) {
  uint32_t loaderVersion = 0;
  if (vkEnumerateInstanceVersion(&loaderVersion) != VK_SUCCESS || loaderVersion < VK_API_VERSION_1_3) {
    return makeError("the Vulkan loader is older than 1.3; install libvulkan1 from Debian 12 or newer");
  }
  bool validation = options.validation;
  if (validation && !hasLayer(kValidationLayer)) {
    if (options.validationRequired) {
      return makeError("validation was requested but VK_LAYER_KHRONOS_validation is not installed; "
                       "install vulkan-validationlayers");
    }
    notes_.push_back("validation layer not installed (vulkan-validationlayers); running without it");
    validation = false;
  }
  const std::vector<std::string> available = instanceExtensionNames(nullptr);
  std::vector<std::string> extensions;
  for (const std::string& e : options.instanceExtensions) {
    if (!contains(available, e)) {
      return makeError("the Vulkan instance lacks extension " + e + " (needed for the window); "
                       "is a display server running?");
    }
    if (!contains(extensions, e)) extensions.push_back(e);
  }
  if (validation) {
    const bool debugUtils = contains(available, VK_EXT_DEBUG_UTILS_EXTENSION_NAME) ||
                            contains(instanceExtensionNames(kValidationLayer), VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    if (!debugUtils) return makeError("validation needs VK_EXT_debug_utils, which this Vulkan loader lacks");
    if (!contains(extensions, VK_EXT_DEBUG_UTILS_EXTENSION_NAME)) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  }
  std::vector<const char*> extensionPtrs;
  for (const std::string& e : extensions) extensionPtrs.push_back(e.c_str());

  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "photowalk";
  app.pEngineName = "photowalk";
  app.apiVersion = VK_API_VERSION_1_3;

  VkDebugUtilsMessengerCreateInfoEXT messengerInfo{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messengerInfo.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messengerInfo.pfnUserCallback = onValidationMessage;
  messengerInfo.pUserData = log_.get();

  // Synchronization validation too: missing barriers are the bugs the core checks miss.
  const VkValidationFeatureEnableEXT enables[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  features.enabledValidationFeatureCount = 1;
  features.pEnabledValidationFeatures = enables;
  features.pNext = &messengerInfo;  // also catches messages from vkCreateInstance itself

  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  info.enabledExtensionCount = static_cast<uint32_t>(extensionPtrs.size());
  info.ppEnabledExtensionNames = extensionPtrs.data();
  if (validation) {
    info.enabledLayerCount = 1;
    info.ppEnabledLayerNames = &kValidationLayer;
    info.pNext = &features;
  }
  VkInstance instance = VK_NULL_HANDLE;
  PW_VK_CHECK(vkCreateInstance(&info, nullptr, &instance));
  instance_.reset(instance);
  enabledInstanceExtensions_ = extensions;

  if (validation) {
    auto createMessenger = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
    if (!createMessenger) return makeError("validation: vkCreateDebugUtilsMessengerEXT is missing from the loader");
    messenger_.instance = instance;
    PW_VK_CHECK(createMessenger(instance, &messengerInfo, nullptr, &messenger_.handle));
  }
  return {};
}

Status Context::pickPhysicalDevice(bool forceCpu) {
  uint32_t count = 0;
  PW_VK_CHECK(vkEnumeratePhysicalDevices(instance(), &count, nullptr));
  std::vector<VkPhysicalDevice> devices(count);
  PW_VK_CHECK(vkEnumeratePhysicalDevices(instance(), &count, devices.data()));
  devices.resize(count);

  std::vector<DeviceCandidate> candidates;
  for (VkPhysicalDevice device : devices) {
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(device, &props);
    DeviceCandidate c{props.deviceName, props.deviceType, props.apiVersion, ""};
    if (props.apiVersion < VK_API_VERSION_1_3) {
      c.missing = "Vulkan 1.3";
    } else {
      VkPhysicalDeviceVulkan13Features f13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
      VkPhysicalDeviceFeatures2 f2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
      f2.pNext = &f13;
      vkGetPhysicalDeviceFeatures2(device, &f2);
      if (!f13.dynamicRendering) c.missing = "dynamicRendering";
      if (!f13.synchronization2) c.missing += std::string(c.missing.empty() ? "" : ", ") + "synchronization2";
    }
    uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &familyCount, families.data());
    if (std::none_of(families.begin(), families.end(), [](const auto& f) { return f.queueFlags & VK_QUEUE_GRAPHICS_BIT; })) {
      c.missing += std::string(c.missing.empty() ? "" : ", ") + "a graphics queue";
    }
    candidates.push_back(std::move(c));
  }
  auto envCpu = cpuDeviceRequestedByEnvironment();
  if (!envCpu) return envCpu.error();
  auto chosen = chooseDevice(candidates, forceCpu || *envCpu);
  if (!chosen) return chosen.error();
  physicalDevice_ = devices[*chosen];
  vkGetPhysicalDeviceProperties(physicalDevice_, &properties_);
  vkGetPhysicalDeviceMemoryProperties(physicalDevice_, &memoryProperties_);
  return {};
}

Status Context::createDevice() {
  uint32_t familyCount = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice_, &familyCount, nullptr);
  std::vector<VkQueueFamilyProperties> families(familyCount);
  vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice_, &familyCount, families.data());
  for (uint32_t i = 0; i < familyCount; ++i) {
    if (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) {
      queueFamily_ = i;
      break;
    }
  }

  VkPhysicalDeviceFeatures supported;
  vkGetPhysicalDeviceFeatures(physicalDevice_, &supported);
  anisotropy_ = supported.samplerAnisotropy == VK_TRUE;

  std::vector<const char*> extensions;
  if (std::find(enabledInstanceExtensions_.begin(), enabledInstanceExtensions_.end(), VK_KHR_SURFACE_EXTENSION_NAME) !=
      enabledInstanceExtensions_.end()) {
    uint32_t count = 0;
    vkEnumerateDeviceExtensionProperties(physicalDevice_, nullptr, &count, nullptr);
    std::vector<VkExtensionProperties> props(count);
    vkEnumerateDeviceExtensionProperties(physicalDevice_, nullptr, &count, props.data());
    swapchain_ = std::any_of(props.begin(), props.end(),
                             [](const auto& p) { return !std::strcmp(p.extensionName, VK_KHR_SWAPCHAIN_EXTENSION_NAME); });
    if (swapchain_) extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    swapchainMutableFormat_ = swapchain_ && std::any_of(props.begin(), props.end(), [](const auto& p) {
      return !std::strcmp(p.extensionName, VK_KHR_SWAPCHAIN_MUTABLE_FORMAT_EXTENSION_NAME);
    });
    if (swapchainMutableFormat_) extensions.push_back(VK_KHR_SWAPCHAIN_MUTABLE_FORMAT_EXTENSION_NAME);
  }

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queueInfo.queueFamilyIndex = queueFamily_;
  queueInfo.queueCount = 1;
  queueInfo.pQueuePriorities = &priority;

  VkPhysicalDeviceVulkan13Features f13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  f13.dynamicRendering = VK_TRUE;
  f13.synchronization2 = VK_TRUE;
  VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  features.pNext = &f13;
  features.features.samplerAnisotropy = anisotropy_ ? VK_TRUE : VK_FALSE;

  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  info.pNext = &features;
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queueInfo;
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  VkDevice device = VK_NULL_HANDLE;
  PW_VK_CHECK(vkCreateDevice(physicalDevice_, &info, nullptr, &device));
  device_.reset(device);
  vkGetDeviceQueue(device, queueFamily_, 0, &queue_);
  return {};
}

Result<uint32_t> Context::memoryType(uint32_t typeBits, VkMemoryPropertyFlags required,
                                     VkMemoryPropertyFlags preferred) const {
  int fallback = -1;
  for (uint32_t i = 0; i < memoryProperties_.memoryTypeCount; ++i) {
    const VkMemoryPropertyFlags flags = memoryProperties_.memoryTypes[i].propertyFlags;
    if (!(typeBits & (1u << i)) || (flags & required) != required) continue;
    if ((flags & preferred) == preferred) return i;
    if (fallback < 0) fallback = static_cast<int>(i);
  }
  if (fallback >= 0) return static_cast<uint32_t>(fallback);
  return makeError("the Vulkan device has no suitable memory type (wanted property flags " + std::to_string(required) + ")");
}

Result<Context::Submission> Context::submit(const std::function<void(VkCommandBuffer)>& record) const {
  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
  poolInfo.queueFamilyIndex = queueFamily_;
  VkCommandPool poolHandle = VK_NULL_HANDLE;
  PW_VK_CHECK(vkCreateCommandPool(device(), &poolInfo, nullptr, &poolHandle));
  OwnedCommandPool pool(device(), poolHandle);

  VkCommandBufferAllocateInfo allocInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  allocInfo.commandPool = pool.get();
  allocInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocInfo.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  PW_VK_CHECK(vkAllocateCommandBuffers(device(), &allocInfo, &cmd));

  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  PW_VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
  record(cmd);
  PW_VK_CHECK(vkEndCommandBuffer(cmd));

  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VkFence fenceHandle = VK_NULL_HANDLE;
  PW_VK_CHECK(vkCreateFence(device(), &fenceInfo, nullptr, &fenceHandle));
  OwnedFence fence(device(), fenceHandle);

  VkCommandBufferSubmitInfo cmdInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
  cmdInfo.commandBuffer = cmd;
  VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
  submit.commandBufferInfoCount = 1;
  submit.pCommandBufferInfos = &cmdInfo;
  PW_VK_CHECK(vkQueueSubmit2(queue_, 1, &submit, fence.get()));
  return Submission{std::move(pool), std::move(fence)};
}

Status Context::submitAndWait(const std::function<void(VkCommandBuffer)>& record) const {
  auto submission = submit(record);
  if (!submission) return submission.error();
  const VkFence fence = submission->fence.get();
  PW_VK_CHECK(vkWaitForFences(device(), 1, &fence, VK_TRUE, UINT64_MAX));
  return {};
}

}  // namespace pw::engine::gpu
