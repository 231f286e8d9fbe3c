// Fences and semaphores: host signals, bounded waits, and a submit that waits for a
// host signal (the draw-patching mechanism of docs/design.md).
#include "tilelight_testing/sync_probes.h"
#include "tilelight_testing/test_support.h"

#include "tilelight/vulkan/barriers.h"
#include "tilelight/vulkan/buffer.h"
#include "tilelight/vulkan/error.h"
#include "tilelight/vulkan/submit.h"
#include "tilelight/vulkan/sync.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>

namespace tilelight {
namespace {

using test::VulkanTest;

TEST_F(VulkanTest, TimelineHostSignalAndWait) {
  const TimelineSemaphore timeline(context(), "frame timeline", 5);
  EXPECT_EQ(timeline.value(), 5u);
  timeline.signal(7);
  EXPECT_EQ(timeline.value(), 7u);
  EXPECT_NO_THROW(timeline.wait(7, "nothing", Seconds{1.0}));
  EXPECT_NO_THROW(timeline.wait(6, "nothing", Seconds{1.0}));  // already passed
}

TEST_F(VulkanTest, TimelineWaitTimesOutWithTheStageName) {
  const TimelineSemaphore timeline(context(), "frame timeline");
  const auto start = std::chrono::steady_clock::now();
  try {
    timeline.wait(1, "the classification pass", Seconds{0.05});
    FAIL() << "no timeout";
  } catch (const TimeoutError& e) {
    EXPECT_STREQ(e.what(), "GPU did not finish the classification pass within 0.05 s");
  }
  // The wait really waited for its timeout instead of failing at once. Only this lower bound
  // holds on a loaded machine; that the wait returns at all is what ctest's TIMEOUT checks.
  // Half the timeout: Vulkan may round the timeout to its timer's accuracy.
  EXPECT_GE(std::chrono::steady_clock::now() - start, std::chrono::milliseconds(25));
}

TEST_F(VulkanTest, TimelineSignalMustIncrease) {
  const TimelineSemaphore timeline(context(), "frame timeline", 3);
  try {
    timeline.signal(3);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "timeline semaphore frame timeline: host signal 3 is not greater than the "
                 "current value 3");
  }
}

TEST_F(VulkanTest, FenceStatesAndBoundedWait) {
  const Fence done(context(), "done", true);
  EXPECT_TRUE(test::is_signaled(context(), done));
  EXPECT_NO_THROW(done.wait("nothing", Seconds{1.0}));
  done.reset();
  EXPECT_FALSE(test::is_signaled(context(), done));
  try {
    done.wait("the G-buffer pass", Seconds{0.02});
    FAIL() << "no timeout";
  } catch (const TimeoutError& e) {
    EXPECT_STREQ(e.what(), "GPU did not finish the G-buffer pass within 0.02 s");
  }
}

TEST_F(VulkanTest, BinarySemaphoreOrdersTwoSubmits) {
  const test::BinarySemaphore between(context(), "between");
  Buffer buffer(context(), {16, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::HostReadback, "ordered"});
  UniqueCommandBuffer first = pool().allocate("first");
  UniqueCommandBuffer second = pool().allocate("second");
  begin_commands(first.get(), "first");
  vkCmdFillBuffer(first.get(), buffer.handle(), 0, VK_WHOLE_SIZE, 1u);
  end_commands(first.get(), "first");
  begin_commands(second.get(), "second");
  vkCmdFillBuffer(second.get(), buffer.handle(), 0, 8, 2u);
  buffer_barrier(second.get(), buffer.handle(), {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT},
                 {VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT});
  end_commands(second.get(), "second");

  const Fence fence(context(), "second done");
  const VkCommandBuffer first_buffers[] = {first.get()};
  const SemaphoreSignal signal[] = {{between.handle(), 0}};
  submit(context(), {first_buffers, {}, signal, VK_NULL_HANDLE}, "first fill");
  const VkCommandBuffer second_buffers[] = {second.get()};
  const SemaphoreWait wait[] = {{between.handle(), 0, VK_PIPELINE_STAGE_TRANSFER_BIT}};
  submit(context(), {second_buffers, wait, {}, fence.handle()}, "second fill");
  fence.wait("the second fill", Seconds{30.0});
  const std::span<const std::uint32_t> words = buffer.as<std::uint32_t>();
  EXPECT_EQ(words[0], 2u);
  EXPECT_EQ(words[1], 2u);
  EXPECT_EQ(words[2], 1u);
  EXPECT_EQ(words[3], 1u);
}

// The tile pass is submitted before the CPU has patched its draws; it waits on a timeline value
// that only the host signals. Nothing may run before the signal; everything runs after it.
TEST_F(VulkanTest, SubmitWaitsForHostSignal) {
  const TimelineSemaphore timeline(context(), "draw patching");
  Buffer target(context(), {64, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::HostReadback, "patched target"});
  std::fill(target.as<std::uint32_t>().begin(), target.as<std::uint32_t>().end(), 0u);

  UniqueCommandBuffer cmd = pool().allocate("pre-recorded tile pass");
  begin_commands(cmd.get(), "pre-recorded tile pass");
  vkCmdFillBuffer(cmd.get(), target.handle(), 0, VK_WHOLE_SIZE, 0xabcd1234u);
  buffer_barrier(cmd.get(), target.handle(), {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT},
                 {VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT});
  end_commands(cmd.get(), "pre-recorded tile pass");

  const VkCommandBuffer buffers[] = {cmd.get()};
  const SemaphoreWait wait[] = {{timeline.handle(), 1, VK_PIPELINE_STAGE_TRANSFER_BIT}};
  const SemaphoreSignal signal[] = {{timeline.handle(), 2}};
  submit(context(), {buffers, wait, signal, VK_NULL_HANDLE}, "the tile pass");

  // No sleep-and-look: the host waits for the batch's own signal. A queue that ran the batch
  // without the host signal would end this wait early (and the checks below would fail); a
  // correct one makes it time out, however slow the machine.
  EXPECT_THROW(timeline.wait(2, "the tile pass", Seconds{0.2}), TimeoutError);
  EXPECT_EQ(timeline.value(), 0u);
  EXPECT_EQ(target.as<std::uint32_t>()[0], 0u);

  timeline.signal(1);  // "draws patched"
  timeline.wait(2, "the tile pass", Seconds{30.0});
  for (const std::uint32_t word : target.as<std::uint32_t>()) {
    ASSERT_EQ(word, 0xabcd1234u);
  }
}

// wait_idle() stands in for vkDeviceWaitIdle/vkQueueWaitIdle, which have no timeout: it must
// give up with the stage's name while the queue is held by a wait the host never signals.
// Without the validation layer: on a timeout the fence is deliberately leaked (destroying a
// pending fence is invalid), and the layer would report the leak when the device goes.
TEST(BoundedWaits, WaitIdleTimesOutWhileTheQueueWaitsForTheHost) {
  ContextOptions options;
  options.validation = false;
  const Context context(options);
  const TimelineSemaphore timeline(context, "never signalled in time");
  const SemaphoreWait wait[] = {{timeline.handle(), 1, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT}};
  submit(context, {{}, wait, {}, VK_NULL_HANDLE}, "a batch waiting for the host");
  try {
    context.wait_idle("the blocked queue", Seconds{0.05});
    FAIL() << "wait_idle returned while the queue was blocked";
  } catch (const TimeoutError& e) {
    EXPECT_STREQ(e.what(), "GPU did not finish the blocked queue within 0.05 s");
  }
  timeline.signal(1);
  EXPECT_NO_THROW(context.wait_idle("the released queue", Seconds{30.0}));
}

}  // namespace
}  // namespace tilelight
