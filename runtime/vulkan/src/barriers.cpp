#include "tilelight/vulkan/barriers.h"

namespace tilelight {

void image_barrier(VkCommandBuffer cmd, VkImage image, const VkImageSubresourceRange& range, VkImageLayout old_layout,
                   VkImageLayout new_layout, Scope src, Scope dst) {
  VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  barrier.srcAccessMask = src.access;
  barrier.dstAccessMask = dst.access;
  barrier.oldLayout = old_layout;
  barrier.newLayout = new_layout;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image;
  barrier.subresourceRange = range;
  vkCmdPipelineBarrier(cmd, src.stages, dst.stages, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

void buffer_barrier(VkCommandBuffer cmd, VkBuffer buffer, Scope src, Scope dst, VkDeviceSize offset,
                    VkDeviceSize size) {
  VkBufferMemoryBarrier barrier{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
  barrier.srcAccessMask = src.access;
  barrier.dstAccessMask = dst.access;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.buffer = buffer;
  barrier.offset = offset;
  barrier.size = size;
  vkCmdPipelineBarrier(cmd, src.stages, dst.stages, 0, 0, nullptr, 1, &barrier, 0, nullptr);
}

void memory_barrier(VkCommandBuffer cmd, Scope src, Scope dst) {
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = src.access;
  barrier.dstAccessMask = dst.access;
  vkCmdPipelineBarrier(cmd, src.stages, dst.stages, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

}  // namespace tilelight
