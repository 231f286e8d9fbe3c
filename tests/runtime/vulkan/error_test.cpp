// Error texts: they are what a user sees when a run fails, so their exact form is tested.
#include "tilelight/vulkan/error.h"
#include "tilelight/vulkan/timeout.h"

#include <gtest/gtest.h>

#include <limits>

namespace tilelight {
namespace {

TEST(Error, VulkanErrorNamesCallObjectAndResult) {
  const VulkanError e(VK_ERROR_OUT_OF_DEVICE_MEMORY, "vkAllocateMemory", "G-buffer RT1");
  EXPECT_STREQ(e.what(), "vkAllocateMemory failed for G-buffer RT1: VK_ERROR_OUT_OF_DEVICE_MEMORY");
  EXPECT_EQ(e.result(), VK_ERROR_OUT_OF_DEVICE_MEMORY);
  EXPECT_STREQ(VulkanError(VK_ERROR_DEVICE_LOST, "vkQueueSubmit", "").what(),
               "vkQueueSubmit failed: VK_ERROR_DEVICE_LOST");
}

TEST(Error, CheckThrowsOnEverythingButSuccess) {
  EXPECT_NO_THROW(check(VK_SUCCESS, "vkCreateFence", "x"));
  EXPECT_THROW(check(VK_TIMEOUT, "vkWaitForFences", "x"), VulkanError);
  EXPECT_THROW(check(VK_ERROR_DEVICE_LOST, "vkQueueSubmit"), VulkanError);
}

TEST(Error, UnknownResultKeepsItsNumber) {
  EXPECT_EQ(result_name(static_cast<VkResult>(-12345)), "VkResult(-12345)");
  EXPECT_EQ(result_name(VK_ERROR_FORMAT_NOT_SUPPORTED), "VK_ERROR_FORMAT_NOT_SUPPORTED");
}

TEST(Timeout, MessageNamesStageAndSeconds) {
  EXPECT_EQ(timeout_message("the tile pass", Seconds{60.0}), "GPU did not finish the tile pass within 60 s");
  EXPECT_EQ(timeout_message("classification", Seconds{0.05}), "GPU did not finish classification within 0.05 s");
  try {
    throw_timeout("the G-buffer pass", Seconds{2.5});
  } catch (const TimeoutError& e) {
    EXPECT_STREQ(e.what(), "GPU did not finish the G-buffer pass within 2.5 s");
  }
}

TEST(Timeout, NanosecondsAreBoundedNeverInfinite) {
  EXPECT_EQ(timeout_ns(Seconds{1.5}), 1'500'000'000u);
  EXPECT_EQ(timeout_ns(Seconds{-1.0}), 0u);
  EXPECT_EQ(timeout_ns(Seconds{std::numeric_limits<double>::quiet_NaN()}), 0u);
  // UINT64_MAX means "wait forever" to Vulkan; a finite request must never become that.
  EXPECT_LT(timeout_ns(Seconds{1e300}), std::numeric_limits<std::uint64_t>::max());
}

}  // namespace
}  // namespace tilelight
