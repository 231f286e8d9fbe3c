#pragma once
// Pipeline-barrier helpers (Vulkan 1.2, so the original vkCmdPipelineBarrier rather than
// synchronization2). Spelling out both halves of every barrier at the call site keeps the
// synchronisation reviewable.

#include <vulkan/vulkan.h>

namespace tilelight {

// One side of a dependency: the stages and the accesses made (src) or about to be made (dst).
struct Scope {
  VkPipelineStageFlags stages = 0;
  VkAccessFlags access = 0;
};

// Layout transition (or plain barrier when old == new) over `range` of `image`.
// Precondition: `cmd` is recording and outside a render pass.
void image_barrier(VkCommandBuffer cmd, VkImage image, const VkImageSubresourceRange& range, VkImageLayout old_layout,
                   VkImageLayout new_layout, Scope src, Scope dst);

// Makes `src` accesses to [offset, offset + size) of `buffer` visible to `dst`.
void buffer_barrier(VkCommandBuffer cmd, VkBuffer buffer, Scope src, Scope dst, VkDeviceSize offset = 0,
                    VkDeviceSize size = VK_WHOLE_SIZE);

// A global memory barrier, e.g. HOST/HOST_WRITE -> DRAW_INDIRECT/INDIRECT_COMMAND_READ for
// records the CPU writes after the submit (docs/design.md, deferred draw patching).
void memory_barrier(VkCommandBuffer cmd, Scope src, Scope dst);

}  // namespace tilelight
