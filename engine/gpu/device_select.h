// Choosing the physical device: discrete GPU > integrated GPU > other GPUs > the CPU
// (lavapipe). The CPU device is never filtered out: it is the fallback on machines
// without a GPU and the device every test runs on. Pure logic, tested without Vulkan.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "base/result.h"

namespace pw::engine::gpu {

struct DeviceCandidate {
  std::string name;
  VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
  uint32_t apiVersion = 0;
  // Empty when the device has everything photowalk needs (Vulkan 1.3, dynamic
  // rendering, synchronization2, a graphics queue); else what it lacks, for the error.
  std::string missing;
};

// Index into `candidates` of the device to use. forceCpu picks the CPU device (an
// error when there is none). The error lists every device and why it was rejected.
Result<size_t> chooseDevice(const std::vector<DeviceCandidate>& candidates, bool forceCpu);

// True when PW_DEVICE=cpu; an error for any other non-empty value.
Result<bool> cpuDeviceRequestedByEnvironment();

}  // namespace pw::engine::gpu
