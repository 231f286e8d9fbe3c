#pragma once
// MSAA sample-count choice for the G-buffer. The book uses 2x; lavapipe supports only 1x and
// 4x, so "auto" takes 2x where the device has it and 4x otherwise, and says which.

#include "tilelight/device_limits.h"

#include <vulkan/vulkan.h>

#include <cstdint>

namespace tilelight {

// Sample counts usable for the G-buffer: supported for colour and depth framebuffer attachments
// and for sampled colour and depth images at once.
VkSampleCountFlags msaa_supported_counts(const DeviceLimits& limits);

// `supported`: msaa_supported_counts() of the device.
// `requested`: 0 = auto (2x if supported, else 4x, else 1x), otherwise 1, 2, 4, 8, 16, 32 or 64.
// Throws tilelight::Error naming the value and the supported counts when an explicit request is
// not a sample count or the device lacks it, e.g.
// "MSAA 2x is not supported by this device (supported for the G-buffer: 1x, 4x)".
VkSampleCountFlagBits choose_msaa(VkSampleCountFlags supported, std::uint32_t requested);

}  // namespace tilelight
