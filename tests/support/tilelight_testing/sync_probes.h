#pragma once
// Vulkan synchronisation the tests need and the renderer does not: a binary semaphore (the
// renderer orders its submits with one timeline semaphore, tilelight/vulkan/sync.h) and a
// non-blocking look at a fence (the renderer only ever waits, with a bound).

#include "tilelight/vulkan/sync.h"
#include "tilelight/vulkan/vk_handles.h"

#include <vulkan/vulkan.h>

#include <string>

namespace tilelight {
class Context;
}

namespace tilelight::test {

// A binary semaphore: GPU-to-GPU ordering between two submits. There is no host wait for
// binary semaphores in Vulkan, hence no wait() here.
class BinarySemaphore {
 public:
  BinarySemaphore(const Context& context, std::string name);

  VkSemaphore handle() const { return semaphore_.get(); }
  const std::string& name() const { return name_; }

 private:
  std::string name_;
  UniqueSemaphore semaphore_;
};

// Whether `fence` is signalled now (vkGetFenceStatus), without waiting. Throws VulkanError on
// device loss.
bool is_signaled(const Context& context, const Fence& fence);

}  // namespace tilelight::test
