#include "tilelight/vulkan/submit.h"

#include "tilelight/vulkan/commands.h"
#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"
#include "tilelight/vulkan/sync.h"

#include <vector>

namespace tilelight {

void submit(const Context& context, const Submission& submission, std::string_view stage) {
  std::vector<VkSemaphore> wait_semaphores;
  std::vector<std::uint64_t> wait_values;
  std::vector<VkPipelineStageFlags> wait_stages;
  for (const SemaphoreWait& wait : submission.waits) {
    wait_semaphores.push_back(wait.semaphore);
    wait_values.push_back(wait.value);
    wait_stages.push_back(wait.stages);
  }
  std::vector<VkSemaphore> signal_semaphores;
  std::vector<std::uint64_t> signal_values;
  for (const SemaphoreSignal& signal : submission.signals) {
    signal_semaphores.push_back(signal.semaphore);
    signal_values.push_back(signal.value);
  }

  // Values for binary semaphores in these arrays are ignored by Vulkan, so one struct serves
  // any mix of binary and timeline semaphores.
  VkTimelineSemaphoreSubmitInfo timeline{VK_STRUCTURE_TYPE_TIMELINE_SEMAPHORE_SUBMIT_INFO};
  timeline.waitSemaphoreValueCount = static_cast<std::uint32_t>(wait_values.size());
  timeline.pWaitSemaphoreValues = wait_values.data();
  timeline.signalSemaphoreValueCount = static_cast<std::uint32_t>(signal_values.size());
  timeline.pSignalSemaphoreValues = signal_values.data();

  VkSubmitInfo info{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  info.pNext = &timeline;
  info.waitSemaphoreCount = static_cast<std::uint32_t>(wait_semaphores.size());
  info.pWaitSemaphores = wait_semaphores.data();
  info.pWaitDstStageMask = wait_stages.data();
  info.commandBufferCount = static_cast<std::uint32_t>(submission.command_buffers.size());
  info.pCommandBuffers = submission.command_buffers.data();
  info.signalSemaphoreCount = static_cast<std::uint32_t>(signal_semaphores.size());
  info.pSignalSemaphores = signal_semaphores.data();
  check(vkQueueSubmit(context.queue(), 1, &info, submission.fence), "vkQueueSubmit", stage);
}

void submit_and_wait(const Context& context, const CommandPool& pool,
                     const std::function<void(VkCommandBuffer)>& record, std::string_view stage, Seconds timeout) {
  UniqueCommandBuffer cmd = pool.allocate(stage);
  begin_commands(cmd.get(), stage);
  record(cmd.get());
  end_commands(cmd.get(), stage);

  Fence fence(context, std::string(stage));
  const VkCommandBuffer buffers[] = {cmd.get()};
  Submission submission;
  submission.command_buffers = buffers;
  submission.fence = fence.handle();
  submit(context, submission, stage);
  try {
    fence.wait(stage, timeout);
  } catch (const TimeoutError&) {
    // Still pending: freeing the command buffer or destroying the fence now would be invalid.
    (void)cmd.release();
    [[maybe_unused]] auto* leaked = new Fence(std::move(fence));
    throw;
  }
}

}  // namespace tilelight
