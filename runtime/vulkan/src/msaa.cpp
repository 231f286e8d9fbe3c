#include "tilelight/vulkan/msaa.h"

#include "tilelight/vulkan/error.h"
#include "tilelight/vulkan/formats.h"

#include <fmt/format.h>

#include <bit>

namespace tilelight {

VkSampleCountFlags msaa_supported_counts(const DeviceLimits& limits) {
  // Vulkan requires 1x for every one of these uses; a driver reporting otherwise is ignored.
  return (limits.framebuffer_color_samples & limits.framebuffer_depth_samples & limits.sampled_color_samples &
          limits.sampled_depth_samples) |
         VK_SAMPLE_COUNT_1_BIT;
}

VkSampleCountFlagBits choose_msaa(VkSampleCountFlags supported, std::uint32_t requested) {
  if (requested == 0) {
    // 2x is the book's choice; 4x is the one count (beside 1x) that Vulkan requires for
    // colour and depth attachments, so it is the portable fallback; 1x only when nothing else.
    for (const VkSampleCountFlagBits candidate :
         {VK_SAMPLE_COUNT_2_BIT, VK_SAMPLE_COUNT_4_BIT, VK_SAMPLE_COUNT_8_BIT, VK_SAMPLE_COUNT_16_BIT}) {
      if ((supported & candidate) != 0) {
        return candidate;
      }
    }
    return VK_SAMPLE_COUNT_1_BIT;
  }
  if (requested > 64 || !std::has_single_bit(requested)) {
    throw Error(
        fmt::format("MSAA {}x is not a sample count (use 0 for auto, or 1, 2, 4, 8, 16, 32, 64; supported "
                    "for the G-buffer: {})",
                    requested, sample_counts_text(supported)));
  }
  // Vulkan's sample-count bits have the value of the count they stand for.
  if ((supported & requested) == 0) {
    throw Error(
        fmt::format("MSAA {}x is not supported by this device (supported for the "
                    "G-buffer: {})",
                    requested, sample_counts_text(supported)));
  }
  return static_cast<VkSampleCountFlagBits>(requested);
}

}  // namespace tilelight
