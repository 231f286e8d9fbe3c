#pragma once
// One indexed indirect draw as the GPU reads it: field for field (names included) the layout
// of VkDrawIndexedIndirectCommand, so the index builder can fill the mapped indirect buffer
// directly without this library knowing Vulkan. The render library checks the layout against
// the Vulkan struct with static_asserts.

#include <cstdint>

namespace tilelight {

// A plain aggregate, as the Vulkan struct is: write `DrawRecord{count, 1, first, 0, 0}`.
struct DrawRecord {
  std::uint32_t indexCount, instanceCount, firstIndex;
  std::int32_t vertexOffset;
  std::uint32_t firstInstance;
};

}  // namespace tilelight
