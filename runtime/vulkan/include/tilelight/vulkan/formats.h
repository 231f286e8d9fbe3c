#pragma once
// Names and texel sizes of the formats the runtime uses. The Vulkan headers on Debian 12 ship
// no enum-to-string helper for C, and error messages should say "VK_FORMAT_R16G16B16A16_SFLOAT"
// rather than "97".

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>

namespace tilelight {

// "VK_FORMAT_R8G8B8A8_UNORM"; "VkFormat(<n>)" for formats this table does not know.
std::string format_name(VkFormat format);

// Bytes per texel of an uncompressed colour or depth format; 0 for formats this table does not
// know (callers that need a size treat 0 as "unsupported").
std::uint32_t texel_size(VkFormat format);

// "1x, 4x": the sample counts set in `counts`, for messages.
std::string sample_counts_text(VkSampleCountFlags counts);

}  // namespace tilelight
