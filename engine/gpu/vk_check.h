// Checking Vulkan results. On in every build type: a failed call is an Error value
// (file:line, the call, the VkResult's name), never an abort or an exception.
#pragma once

#include <string>

#include <vulkan/vulkan.h>

#include "base/result.h"

namespace pw::engine::gpu {

// "VK_ERROR_OUT_OF_DEVICE_MEMORY", or the number for codes this build does not know.
const char* vkResultName(VkResult result);

// The message PW_VK_CHECK returns; out-of-memory results get a hint a person can act on.
Error vkCallError(const char* file, int line, const char* call, VkResult result);

}  // namespace pw::engine::gpu

// Evaluates a Vulkan call; on failure returns its Error from the enclosing function
// (which returns Status or Result<T>).
#define PW_VK_CHECK(call)                                                                   \
  do {                                                                                      \
    const VkResult pwVkResult_ = (call);                                                    \
    if (pwVkResult_ < 0) return ::pw::engine::gpu::vkCallError(__FILE__, __LINE__, #call, pwVkResult_); \
  } while (0)
