#include "tilelight/vulkan/sync.h"

#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <fmt/format.h>

#include <utility>

namespace tilelight {

UniqueSemaphore create_semaphore(const Context& context, const std::string& name, const void* next) {
  VkSemaphoreCreateInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
  info.pNext = next;
  VkSemaphore semaphore = VK_NULL_HANDLE;
  check(vkCreateSemaphore(context.device(), &info, nullptr, &semaphore), "vkCreateSemaphore", name);
  UniqueSemaphore owned(semaphore, {context.device()});
  context.name_object(semaphore, name);
  return owned;
}

Fence::Fence(const Context& context, std::string name, bool signaled)
    : device_(context.device()), name_(std::move(name)) {
  VkFenceCreateInfo info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  info.flags = signaled ? VkFenceCreateFlags{VK_FENCE_CREATE_SIGNALED_BIT} : VkFenceCreateFlags{0};
  VkFence fence = VK_NULL_HANDLE;
  check(vkCreateFence(device_, &info, nullptr, &fence), "vkCreateFence", name_);
  fence_ = UniqueFence(fence, {device_});
  context.name_object(fence, name_);
}

void Fence::wait(std::string_view stage, Seconds timeout) const {
  const VkFence fence = fence_.get();
  const VkResult result = vkWaitForFences(device_, 1, &fence, VK_TRUE, timeout_ns(timeout));
  if (result == VK_TIMEOUT) {
    throw_timeout(stage, timeout);
  }
  check(result, "vkWaitForFences", name_);
}

void Fence::reset() const {
  const VkFence fence = fence_.get();
  check(vkResetFences(device_, 1, &fence), "vkResetFences", name_);
}

TimelineSemaphore::TimelineSemaphore(const Context& context, std::string name, std::uint64_t initial_value)
    : device_(context.device()), name_(std::move(name)) {
  VkSemaphoreTypeCreateInfo type{VK_STRUCTURE_TYPE_SEMAPHORE_TYPE_CREATE_INFO};
  type.semaphoreType = VK_SEMAPHORE_TYPE_TIMELINE;
  type.initialValue = initial_value;
  semaphore_ = create_semaphore(context, name_, &type);
}

std::uint64_t TimelineSemaphore::value() const {
  std::uint64_t value = 0;
  check(vkGetSemaphoreCounterValue(device_, semaphore_.get(), &value), "vkGetSemaphoreCounterValue", name_);
  return value;
}

void TimelineSemaphore::signal(std::uint64_t new_value) const {
  const std::uint64_t current = value();
  if (new_value <= current) {
    throw Error(
        fmt::format("timeline semaphore {}: host signal {} is not greater than the "
                    "current value {}",
                    name_, new_value, current));
  }
  VkSemaphoreSignalInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_SIGNAL_INFO};
  info.semaphore = semaphore_.get();
  info.value = new_value;
  check(vkSignalSemaphore(device_, &info), "vkSignalSemaphore", name_);
}

void TimelineSemaphore::wait(std::uint64_t target, std::string_view stage, Seconds timeout) const {
  const VkSemaphore semaphore = semaphore_.get();
  VkSemaphoreWaitInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_WAIT_INFO};
  info.semaphoreCount = 1;
  info.pSemaphores = &semaphore;
  info.pValues = &target;
  const VkResult result = vkWaitSemaphores(device_, &info, timeout_ns(timeout));
  if (result == VK_TIMEOUT) {
    throw_timeout(stage, timeout);
  }
  check(result, "vkWaitSemaphores", name_);
}

}  // namespace tilelight
