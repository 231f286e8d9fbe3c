#include "tilelight/vulkan/commands.h"

#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <utility>

namespace tilelight {

CommandPool::CommandPool(const Context& context, std::string name, VkCommandPoolCreateFlags flags)
    : context_(&context), name_(std::move(name)) {
  VkCommandPoolCreateInfo info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  info.flags = flags;
  info.queueFamilyIndex = context.queue_family();
  VkCommandPool pool = VK_NULL_HANDLE;
  check(vkCreateCommandPool(context.device(), &info, nullptr, &pool), "vkCreateCommandPool", name_);
  pool_ = UniqueCommandPool(pool, {context.device()});
  context.name_object(pool, name_);
}

UniqueCommandBuffer CommandPool::allocate(std::string_view name) const {
  VkCommandBufferAllocateInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  info.commandPool = pool_.get();
  info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  info.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  check(vkAllocateCommandBuffers(context_->device(), &info, &cmd), "vkAllocateCommandBuffers", name);
  UniqueCommandBuffer owned(cmd, {context_->device(), pool_.get()});
  context_->name_object(cmd, name);
  return owned;
}

void begin_commands(VkCommandBuffer cmd, std::string_view name, VkCommandBufferUsageFlags usage) {
  VkCommandBufferBeginInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  info.flags = usage;
  check(vkBeginCommandBuffer(cmd, &info), "vkBeginCommandBuffer", name);
}

void end_commands(VkCommandBuffer cmd, std::string_view name) {
  check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer", name);
}

}  // namespace tilelight
