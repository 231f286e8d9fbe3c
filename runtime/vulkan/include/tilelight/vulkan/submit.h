#pragma once
// Queue submission: the general form (with timeline and binary semaphores) and a one-shot
// helper for setup and readback work.

#include "tilelight/vulkan/timeout.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <functional>
#include <span>
#include <string_view>

namespace tilelight {

class Context;
class CommandPool;

struct SemaphoreWait {
  VkSemaphore semaphore = VK_NULL_HANDLE;
  std::uint64_t value = 0;  // timeline value to wait for; ignored for binary semaphores
  VkPipelineStageFlags stages = VK_PIPELINE_STAGE_ALL_COMMANDS_BIT;  // what waits
};

struct SemaphoreSignal {
  VkSemaphore semaphore = VK_NULL_HANDLE;
  std::uint64_t value = 0;  // timeline value to set; ignored for binary semaphores
};

struct Submission {
  std::span<const VkCommandBuffer> command_buffers;
  std::span<const SemaphoreWait> waits;
  std::span<const SemaphoreSignal> signals;
  VkFence fence = VK_NULL_HANDLE;  // optional; signalled when the batch completes
};

// One vkQueueSubmit of one batch on the context's queue. A wait on a timeline value that only
// the host will signal later is allowed (wait-before-signal); a wait on a value that only a
// later submit on this same queue would signal can deadlock (docs/design.md, deferred draw patching).
// `stage` names the work in errors.
void submit(const Context& context, const Submission& submission, std::string_view stage);

// Records `record` into a fresh command buffer from `pool`, submits it alone and waits for it
// with `timeout`. For uploads, clears and readbacks, not per-frame work. If the wait times out,
// the command buffer and fence are leaked on purpose (the GPU may still use them) and
// TimeoutError is thrown.
void submit_and_wait(const Context& context, const CommandPool& pool,
                     const std::function<void(VkCommandBuffer)>& record, std::string_view stage,
                     Seconds timeout = kDefaultGpuTimeout);

}  // namespace tilelight
