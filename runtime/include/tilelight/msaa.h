#pragma once
// MSAA sample-count choice for the G-buffer. The book uses 2x; lavapipe supports only 4x (beside
// 1x), so "auto" takes 2x where the device has it and 4x otherwise, and says which. The G-buffer
// is always multisampled: the lighting and the classification read it as sampler2DMS, which a
// single-sampled image may not be bound to.

#include "tilelight/device_limits.h"

#include <vulkan/vulkan.h>

#include <cstdint>

namespace tilelight {

// Sample counts usable for the G-buffer: 2 or more, supported for colour and depth framebuffer
// attachments and for sampled colour and depth images at once.
VkSampleCountFlags msaa_supported_counts(const DeviceLimits& limits);

// `supported`: msaa_supported_counts() of the device.
// `requested`: 0 = auto (2x if supported, else 4x, else the smallest larger count), otherwise 2,
// 4, 8, 16, 32 or 64. Throws tilelight::Error naming the value and the supported counts when an
// explicit request is 1, not a sample count or lacking on the device, e.g.
// "MSAA 2x is not supported by this device (supported for the G-buffer: 4x)", and when auto
// finds no count at all.
VkSampleCountFlagBits choose_msaa(VkSampleCountFlags supported, std::uint32_t requested);

}  // namespace tilelight
