#pragma once
// Fences and timeline semaphores, what the renderer synchronises with (the tests' binary
// semaphore is in their support library). Every wait here is bounded and throws TimeoutError
// ("GPU did not finish <stage> within N s") instead of blocking forever.

#include "tilelight/vulkan/timeout.h"
#include "tilelight/vulkan/vk_handles.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <string_view>

namespace tilelight {

class Context;

class Fence {
 public:
  Fence() = default;
  Fence(const Context& context, std::string name, bool signaled = false);

  VkFence handle() const { return fence_.get(); }
  const std::string& name() const { return name_; }

  // Waits until the fence is signalled; throws TimeoutError naming `stage` after `timeout`,
  // VulkanError on device loss. Precondition: the fence was submitted (or created signalled),
  // or another thread will submit it.
  void wait(std::string_view stage, Seconds timeout = kDefaultGpuTimeout) const;
  // Precondition: the fence is not pending in a queue.
  void reset() const;

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  std::string name_;
  UniqueFence fence_;
};

// A new semaphore named `name` for the validation layer's messages; `next` is the create info's
// pNext chain (a VkSemaphoreTypeCreateInfo for a timeline semaphore; nullptr: a binary one).
// Throws VulkanError.
UniqueSemaphore create_semaphore(const Context& context, const std::string& name, const void* next = nullptr);

// A timeline semaphore (Vulkan 1.2 core): a 64-bit counter that the GPU or the host raises and
// either side waits for. The draw-patching path uses it both ways: submit 1 signals "tile IDs
// copied", the host waits for that, patches the draws and signals "draws ready" from the host
// with signal(), on which the already-submitted tile pass waits.
class TimelineSemaphore {
 public:
  TimelineSemaphore() = default;
  TimelineSemaphore(const Context& context, std::string name, std::uint64_t initial_value = 0);

  VkSemaphore handle() const { return semaphore_.get(); }
  const std::string& name() const { return name_; }

  // The current counter value (vkGetSemaphoreCounterValue).
  std::uint64_t value() const;

  // Host signal (vkSignalSemaphore). Precondition (checked against the current value):
  // `value` is greater than the counter and than every pending signal of this semaphore.
  void signal(std::uint64_t value) const;

  // Waits until the counter reaches `value`; throws TimeoutError naming `stage` after
  // `timeout`.
  void wait(std::uint64_t value, std::string_view stage, Seconds timeout = kDefaultGpuTimeout) const;

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  std::string name_;
  UniqueSemaphore semaphore_;
};

}  // namespace tilelight
