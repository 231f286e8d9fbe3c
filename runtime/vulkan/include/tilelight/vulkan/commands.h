#pragma once
// Command pools and buffers. A pool, and every buffer allocated from it, must be used by one
// thread at a time (Vulkan's external-synchronisation rule for pools).

#include "tilelight/vulkan/vk_handles.h"

#include <vulkan/vulkan.h>

#include <string>
#include <string_view>

namespace tilelight {

class Context;

class CommandPool {
 public:
  CommandPool() = default;
  // A pool on the context's queue family. The default flag lets each buffer be re-recorded
  // on its own (vkBeginCommandBuffer resets it implicitly).
  CommandPool(const Context& context, std::string name,
              VkCommandPoolCreateFlags flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT);

  VkCommandPool handle() const { return pool_.get(); }
  const std::string& name() const { return name_; }

  // A primary command buffer, freed back to this pool when the handle dies. The pool must
  // outlive it. `name` appears in errors and validation messages.
  UniqueCommandBuffer allocate(std::string_view name) const;

 private:
  const Context* context_ = nullptr;
  std::string name_;
  UniqueCommandPool pool_;
};

// vkBeginCommandBuffer / vkEndCommandBuffer with checked results. `name` is the command
// buffer's name for the error message.
void begin_commands(VkCommandBuffer cmd, std::string_view name,
                    VkCommandBufferUsageFlags usage = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT);
void end_commands(VkCommandBuffer cmd, std::string_view name);

}  // namespace tilelight
