#include "tilelight/vulkan/formats.h"

#include <fmt/format.h>

#include <vector>

namespace tilelight {
namespace {

struct FormatInfo {
  VkFormat format;
  const char* name;
  std::uint32_t size;
};

// Only formats that the runtime creates or reads back; extend as passes need more.
constexpr FormatInfo kFormats[] = {
#define TILELIGHT_FORMAT(name, size) {name, #name, size},
    TILELIGHT_FORMAT(VK_FORMAT_R8_UNORM, 1) TILELIGHT_FORMAT(VK_FORMAT_R8_UINT, 1)
        TILELIGHT_FORMAT(VK_FORMAT_R8G8_UNORM, 2) TILELIGHT_FORMAT(VK_FORMAT_R8G8B8A8_UNORM, 4) TILELIGHT_FORMAT(
            VK_FORMAT_R8G8B8A8_SRGB, 4) TILELIGHT_FORMAT(VK_FORMAT_R8G8B8A8_UINT, 4)
            TILELIGHT_FORMAT(VK_FORMAT_B8G8R8A8_UNORM, 4) TILELIGHT_FORMAT(VK_FORMAT_B8G8R8A8_SRGB, 4) TILELIGHT_FORMAT(
                VK_FORMAT_A2B10G10R10_UNORM_PACK32, 4) TILELIGHT_FORMAT(VK_FORMAT_R16_SFLOAT, 2)
                TILELIGHT_FORMAT(VK_FORMAT_R16_UINT, 2) TILELIGHT_FORMAT(VK_FORMAT_R16G16_SFLOAT, 4) TILELIGHT_FORMAT(
                    VK_FORMAT_R16G16B16A16_SFLOAT, 8) TILELIGHT_FORMAT(VK_FORMAT_R16G16B16A16_UNORM, 8)
                    TILELIGHT_FORMAT(VK_FORMAT_R32_SFLOAT, 4) TILELIGHT_FORMAT(VK_FORMAT_R32_UINT, 4) TILELIGHT_FORMAT(
                        VK_FORMAT_R32G32_SFLOAT, 8) TILELIGHT_FORMAT(VK_FORMAT_R32G32B32A32_SFLOAT, 16)
                        TILELIGHT_FORMAT(VK_FORMAT_R32G32B32A32_UINT, 16) TILELIGHT_FORMAT(VK_FORMAT_D16_UNORM, 2)
                            TILELIGHT_FORMAT(VK_FORMAT_D32_SFLOAT, 4) TILELIGHT_FORMAT(VK_FORMAT_X8_D24_UNORM_PACK32, 4)
                                TILELIGHT_FORMAT(VK_FORMAT_D24_UNORM_S8_UINT, 4)
#undef TILELIGHT_FORMAT
};

const FormatInfo* find(VkFormat format) {
  for (const FormatInfo& info : kFormats) {
    if (info.format == format) {
      return &info;
    }
  }
  return nullptr;
}

}  // namespace

std::string format_name(VkFormat format) {
  const FormatInfo* info = find(format);
  return info != nullptr ? std::string(info->name) : fmt::format("VkFormat({})", static_cast<int>(format));
}

std::uint32_t texel_size(VkFormat format) {
  const FormatInfo* info = find(format);
  return info != nullptr ? info->size : 0;
}

std::string sample_counts_text(VkSampleCountFlags counts) {
  std::vector<std::string> parts;
  for (std::uint32_t bit = 1; bit <= 64; bit <<= 1) {
    if ((counts & bit) != 0) {
      parts.push_back(fmt::format("{}x", bit));
    }
  }
  return parts.empty() ? std::string("none") : fmt::format("{}", fmt::join(parts, ", "));
}

}  // namespace tilelight
