#pragma once
// MSAA sample-count choice for the G-buffer. The book uses 2x; lavapipe supports only 4x (beside
// 1x), so "auto" takes 2x where the device has it and 4x otherwise, and says which. 1x (no MSAA,
// as most engines that resolve edges temporally render) is always available: the shaders that
// read a single-sampled G-buffer come from the domain's single-sampled build (shader_registry.h).

#include "tilelight/vulkan/device_limits.h"

#include <vulkan/vulkan.h>

#include <cstdint>

namespace tilelight {

// Sample counts usable for the G-buffer: those supported for colour and depth framebuffer
// attachments and for sampled colour and depth images at once (1x always is, by the spec).
VkSampleCountFlags msaa_supported_counts(const DeviceLimits& limits);

// `supported`: msaa_supported_counts() of the device.
// `requested`: 0 = auto (2x if supported, else 4x, else the smallest larger count, else 1x),
// otherwise 1, 2, 4, 8, 16, 32 or 64. Throws tilelight::Error naming the value and the
// supported counts when an explicit request is not a sample count or lacking on the device, e.g.
// "MSAA 2x is not supported by this device (supported for the G-buffer: 1x, 4x)".
VkSampleCountFlagBits choose_msaa(VkSampleCountFlags supported, std::uint32_t requested);

}  // namespace tilelight
