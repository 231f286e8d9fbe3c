#pragma once
// Errors of the Vulkan layer. Every VkResult is checked, in release builds too: a GPU error
// that is ignored shows up much later as a wrong image, which is far harder to trace.

#include "tilelight/base/error.h"

#include <vulkan/vulkan.h>

#include <string>
#include <string_view>

namespace tilelight {

// A Vulkan call returned an error code.
// what(): "<call> failed for <object>: <VK_RESULT_NAME>", e.g.
// "vkAllocateMemory failed for G-buffer RT1: VK_ERROR_OUT_OF_DEVICE_MEMORY".
class VulkanError : public Error {
 public:
  VulkanError(VkResult result, std::string_view call, std::string_view object);

  VkResult result() const noexcept { return result_; }

 private:
  VkResult result_;
};

// A bounded wait expired: "GPU did not finish <stage> within <N> s".
class TimeoutError : public Error {
 public:
  using Error::Error;
};

// The symbolic name of a VkResult ("VK_ERROR_DEVICE_LOST"); "VkResult(<n>)" otherwise.
std::string result_name(VkResult result);

// Throws VulkanError unless `result` is VK_SUCCESS.
// `call` names the Vulkan function ("vkCreateDevice"); `object` says what it was for ("the
// logical device", "G-buffer RT1"); an empty `object` drops the " for ..." part. Success
// codes other than VK_SUCCESS (VK_TIMEOUT, VK_NOT_READY, VK_INCOMPLETE) count as errors here:
// callers that expect them test the result before calling check().
void check(VkResult result, std::string_view call, std::string_view object = {});

}  // namespace tilelight
