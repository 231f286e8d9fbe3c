#include "tilelight_testing/sync_probes.h"

#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <utility>

namespace tilelight::test {

BinarySemaphore::BinarySemaphore(const Context& context, std::string name)
    : name_(std::move(name)), semaphore_(create_semaphore(context, name_)) {}

bool is_signaled(const Context& context, const Fence& fence) {
  const VkResult result = vkGetFenceStatus(context.device(), fence.handle());
  if (result == VK_NOT_READY) return false;
  check(result, "vkGetFenceStatus", fence.name());
  return true;
}

}  // namespace tilelight::test
