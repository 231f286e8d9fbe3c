// Named timestamps: milliseconds in write order, an error for a full pool. (Reading results
// before the work finished cannot be tested on lavapipe: vkGetQueryPoolResults blocks there
// until the queue is idle.)
#include "tilelight_testing/test_support.h"

#include "tilelight/vulkan/buffer.h"
#include "tilelight/vulkan/error.h"
#include "tilelight/vulkan/submit.h"
#include "tilelight/vulkan/timestamps.h"

#include <gtest/gtest.h>

namespace tilelight {
namespace {

using test::VulkanTest;

TEST(Timestamps, DeltaHandlesWrapAround) {
  EXPECT_EQ(timestamp_delta(10, 25, 64), 15u);
  EXPECT_EQ(timestamp_delta(0xfff0, 0x0010, 16), 0x20u);  // wrapped once in 16 bits
  EXPECT_EQ(timestamp_delta(~std::uint64_t{0}, 4, 64), 5u);
}

TEST_F(VulkanTest, TimestampsInWriteOrder) {
  TimestampQueries timings(context(), "frame timings", 4);
  Buffer scratch(context(), {1 << 16, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::DeviceLocal, "timed work"});
  submit_and_wait(
      context(), pool(),
      [&](VkCommandBuffer cmd) {
        timings.reset(cmd);
        timings.write(cmd, "start", VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT);
        vkCmdFillBuffer(cmd, scratch.handle(), 0, VK_WHOLE_SIZE, 0u);
        timings.write(cmd, "filled");
      },
      "timed work", Seconds{30.0});
  const std::vector<Timestamp> stamps = timings.read();
  ASSERT_EQ(stamps.size(), 2u);
  EXPECT_EQ(stamps[0].label, "start");
  EXPECT_EQ(stamps[0].ms, 0.0);
  EXPECT_EQ(stamps[1].label, "filled");
  EXPECT_GE(stamps[1].ms, 0.0);
  EXPECT_LT(stamps[1].ms, 10'000.0);
  EXPECT_EQ(timings.elapsed_ms("start", "filled"), stamps[1].ms);
  EXPECT_THROW(timings.elapsed_ms("start", "missing"), Error);
}

// Two pools, one queue: a span from the first pool's stamp to the second's, written later in the
// same submission, is their tick difference, and within one pool it is what `ms` says.
TEST_F(VulkanTest, SpanAcrossPoolsUsesTheOneClock) {
  TimestampQueries first(context(), "first", 2), second(context(), "second", 2);
  submit_and_wait(
      context(), pool(),
      [&](VkCommandBuffer cmd) {
        first.reset(cmd);
        second.reset(cmd);
        first.write(cmd, "a");
        first.write(cmd, "b");
        second.write(cmd, "c");
      },
      "two pools", Seconds{30.0});
  const std::vector<Timestamp> early = first.read();
  const std::vector<Timestamp> late = second.read();
  ASSERT_EQ(early.size(), 2u);
  ASSERT_EQ(late.size(), 1u);
  EXPECT_EQ(first.span_ms(early[0], early[1]), early[1].ms);
  EXPECT_GE(late[0].ticks, early[1].ticks);
  EXPECT_GE(second.span_ms(early[0], late[0]), first.span_ms(early[0], early[1]));
  EXPECT_LT(second.span_ms(early[0], late[0]), 10'000.0);
}

TEST_F(VulkanTest, FullPoolIsAnError) {
  TimestampQueries timings(context(), "tiny", 1);
  UniqueCommandBuffer cmd = pool().allocate("timestamps");
  begin_commands(cmd.get(), "timestamps");
  timings.reset(cmd.get());
  timings.write(cmd.get(), "one");
  try {
    timings.write(cmd.get(), "two");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "timestamps tiny: all 1 queries are used (writing \"two\")");
  }
  end_commands(cmd.get(), "timestamps");
}

}  // namespace
}  // namespace tilelight
