#include "engine/gpu/device_select.h"

#include <cstdlib>
#include <string_view>

namespace pw::engine::gpu {
namespace {

int preference(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 4;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 3;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 1;
    default: return 0;
  }
}

const char* typeName(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete GPU";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated GPU";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual GPU";
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return "CPU";
    default: return "other";
  }
}

}  // namespace

Result<size_t> chooseDevice(const std::vector<DeviceCandidate>& candidates, bool forceCpu) {
  if (candidates.empty()) {
    return makeError("no Vulkan device found; install mesa-vulkan-drivers for the CPU renderer (lavapipe)");
  }
  size_t best = candidates.size();
  std::string rejected;
  for (size_t i = 0; i < candidates.size(); ++i) {
    const DeviceCandidate& c = candidates[i];
    if (!c.missing.empty()) {
      rejected += (rejected.empty() ? "" : "; ") + c.name + " lacks " + c.missing;
      continue;
    }
    if (forceCpu && c.type != VK_PHYSICAL_DEVICE_TYPE_CPU) continue;
    if (best == candidates.size() || preference(c.type) > preference(candidates[best].type)) best = i;
  }
  if (best != candidates.size()) return best;
  std::string seen;
  for (const DeviceCandidate& c : candidates) seen += (seen.empty() ? "" : ", ") + c.name + " (" + typeName(c.type) + ")";
  if (forceCpu) {
    return makeError("the CPU device was requested (PW_DEVICE=cpu or --cpu) but the only Vulkan devices are " + seen +
                     (rejected.empty() ? "" : " [" + rejected + "]") + "; install mesa-vulkan-drivers for lavapipe");
  }
  return makeError("no usable Vulkan 1.3 device: " + rejected + "; install mesa-vulkan-drivers for the CPU renderer");
}

Result<bool> cpuDeviceRequestedByEnvironment() {
  const char* value = std::getenv("PW_DEVICE");
  if (!value || !*value) return false;
  const std::string_view v(value);
  if (v == "cpu") return true;
  if (v == "auto") return false;
  return makeError("PW_DEVICE=" + std::string(v) + " is not understood; use PW_DEVICE=cpu (lavapipe) or leave it unset");
}

}  // namespace pw::engine::gpu
