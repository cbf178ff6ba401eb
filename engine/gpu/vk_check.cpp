#include "engine/gpu/vk_check.h"

#include <filesystem>

namespace pw::engine::gpu {

const char* vkResultName(VkResult result) {
  switch (result) {
#define PW_CASE(name) \
  case name:          \
    return #name;
    PW_CASE(VK_SUCCESS)
    PW_CASE(VK_NOT_READY)
    PW_CASE(VK_TIMEOUT)
    PW_CASE(VK_EVENT_SET)
    PW_CASE(VK_EVENT_RESET)
    PW_CASE(VK_INCOMPLETE)
    PW_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
    PW_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    PW_CASE(VK_ERROR_INITIALIZATION_FAILED)
    PW_CASE(VK_ERROR_DEVICE_LOST)
    PW_CASE(VK_ERROR_MEMORY_MAP_FAILED)
    PW_CASE(VK_ERROR_LAYER_NOT_PRESENT)
    PW_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
    PW_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
    PW_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
    PW_CASE(VK_ERROR_TOO_MANY_OBJECTS)
    PW_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
    PW_CASE(VK_ERROR_FRAGMENTED_POOL)
    PW_CASE(VK_ERROR_UNKNOWN)
    PW_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
    PW_CASE(VK_ERROR_INVALID_EXTERNAL_HANDLE)
    PW_CASE(VK_ERROR_FRAGMENTATION)
    PW_CASE(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
    PW_CASE(VK_PIPELINE_COMPILE_REQUIRED)
    PW_CASE(VK_ERROR_SURFACE_LOST_KHR)
    PW_CASE(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR)
    PW_CASE(VK_SUBOPTIMAL_KHR)
    PW_CASE(VK_ERROR_OUT_OF_DATE_KHR)
    PW_CASE(VK_ERROR_INCOMPATIBLE_DISPLAY_KHR)
    PW_CASE(VK_ERROR_VALIDATION_FAILED_EXT)
#undef PW_CASE
    default:
      return "VkResult (unknown code)";
  }
}

Error vkCallError(const char* file, int line, const char* call, VkResult result) {
  std::string message = std::filesystem::path(file).filename().string() + ":" + std::to_string(line) + ": " + call +
                        " failed with " + vkResultName(result);
  if (result == VK_ERROR_OUT_OF_DEVICE_MEMORY || result == VK_ERROR_OUT_OF_HOST_MEMORY) {
    message += " (try a smaller --size or --msaa 1)";
  } else if (result == VK_ERROR_DEVICE_LOST) {
    message += " (the GPU driver reset; try again, or PW_DEVICE=cpu for the CPU renderer)";
  }
  return makeError(std::move(message));
}

}  // namespace pw::engine::gpu
