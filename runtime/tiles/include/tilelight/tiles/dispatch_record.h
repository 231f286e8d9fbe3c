#pragma once
// One indirect compute dispatch as the GPU reads it: field for field the layout of
// VkDispatchIndirectCommand, so the tile-list builder can fill the mapped indirect buffer
// directly without this library knowing Vulkan. The render library checks the layout against
// the Vulkan struct with static_asserts.

#include <cstdint>

namespace tilelight {

// A plain aggregate, as the Vulkan struct is: write `DispatchRecord{groups, 1, 1}`.
struct DispatchRecord {
  std::uint32_t x, y, z;
};

}  // namespace tilelight
