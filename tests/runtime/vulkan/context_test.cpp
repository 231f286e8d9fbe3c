// The context on lavapipe: validation on and silent, limits read, the log really records.
#include "tilelight_testing/context_test_seam.h"
#include "tilelight_testing/test_support.h"

#include "tilelight/vulkan/error.h"

#include <gtest/gtest.h>

namespace tilelight {
namespace {

using test::VulkanTest;

TEST(ContextOnLavapipe, ValidationEnabledAndSilent) {
  ContextOptions options;
  options.validation = true;
  std::shared_ptr<const ValidationLog> log;
  {
    Context context(options);
    log = ContextTestSeam::shared_validation_log(context);
    EXPECT_TRUE(context.validation_enabled());
    EXPECT_NE(context.device(), VK_NULL_HANDLE);
    EXPECT_NE(context.queue(), VK_NULL_HANDLE);
    EXPECT_NO_THROW(context.require_no_validation_messages("context creation"));
  }
  // Also nothing while the device and instance were destroyed.
  EXPECT_EQ(log->count(), 0u) << log->summary();
}

TEST(ContextOnLavapipe, SynchronizationValidationCanBeEnabled) {
  ContextOptions options;
  options.validation = true;
  options.synchronization_validation = true;
  Context context(options);
  EXPECT_EQ(ContextTestSeam::validation_log(context).count(), 0u) << ContextTestSeam::validation_log(context).summary();
}

TEST(ContextOnLavapipe, SynchronizationValidationNeedsValidation) {
  ContextOptions options;
  options.synchronization_validation = true;
  EXPECT_THROW(Context{options}, Error);
}

TEST(ContextOnLavapipe, WithoutValidationThereIsNoLog) {
  Context context;
  EXPECT_FALSE(context.validation_enabled());
  EXPECT_TRUE(ContextTestSeam::validation_log(context).empty());
}

TEST(ContextOnLavapipe, LimitsAndFeatures) {
  Context context;
  const DeviceLimits& limits = context.limits();
  EXPECT_GE(limits.max_framebuffer_width, 1280u);
  EXPECT_GE(limits.max_framebuffer_height, 720u);
  EXPECT_GT(limits.timestamp_period_ns, 0.0f);
  EXPECT_GT(limits.timestamp_valid_bits, 0u);
  EXPECT_GT(limits.subgroup_size, 0u);
  EXPECT_NE(limits.framebuffer_color_samples & VK_SAMPLE_COUNT_4_BIT, 0u);
  EXPECT_GE(VK_API_VERSION_MINOR(context.properties().apiVersion), 2u);
  // lavapipe has both; the draw-patching path can use either indirect form.
  EXPECT_TRUE(context.features().draw_indirect_count);
  EXPECT_TRUE(context.features().multi_draw_indirect);
}

TEST_F(VulkanTest, WaitIdleWithNothingPendingReturns) { EXPECT_NO_THROW(context().wait_idle("nothing", Seconds{5.0})); }

// The log records what the layer says: an injected message and a real misuse both count, and
// require_no_validation_messages() turns them into an error.
TEST_F(VulkanTest, ValidationMessagesAreCountedAndFailTheRun) {
  ValidationLog& log = ContextTestSeam::validation_log(context());
  auto submit_message = reinterpret_cast<PFN_vkSubmitDebugUtilsMessageEXT>(
      vkGetInstanceProcAddr(context().instance(), "vkSubmitDebugUtilsMessageEXT"));
  ASSERT_NE(submit_message, nullptr);
  VkDebugUtilsMessengerCallbackDataEXT data{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CALLBACK_DATA_EXT};
  data.pMessageIdName = "TEST-injected";
  data.pMessage = "injected by the test";
  submit_message(context().instance(), VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT,
                 VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT, &data);
  ASSERT_GE(log.count(), 1u);
  EXPECT_NE(log.summary().find("[error] TEST-injected: injected by the test"), std::string::npos) << log.summary();

  // A buffer with no usage flags is invalid (VUID-VkBufferCreateInfo-usage-requiredbitmask);
  // lavapipe creates it anyway, so the call is safe to make.
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = 16;
  info.usage = 0;
  VkBuffer buffer = VK_NULL_HANDLE;
  const std::size_t before = log.count();
  const VkResult result = vkCreateBuffer(context().device(), &info, nullptr, &buffer);
  if (result == VK_SUCCESS) {
    vkDestroyBuffer(context().device(), buffer, nullptr);
  }
  EXPECT_GT(log.count(), before) << log.summary();
  EXPECT_NE(log.summary().find("usage"), std::string::npos) << log.summary();

  try {
    context().require_no_validation_messages("the test frame");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("the test frame: the validation layer reported"), std::string::npos)
        << e.what();
  }
  log.clear();
}

TEST_F(VulkanTest, IgnoredIdsAreCountedSeparately) {
  ValidationLog& log = ContextTestSeam::validation_log(context());
  log.ignore("TEST-known-layer-bug", "test of the filter");
  auto submit_message = reinterpret_cast<PFN_vkSubmitDebugUtilsMessageEXT>(
      vkGetInstanceProcAddr(context().instance(), "vkSubmitDebugUtilsMessageEXT"));
  ASSERT_NE(submit_message, nullptr);
  VkDebugUtilsMessengerCallbackDataEXT data{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CALLBACK_DATA_EXT};
  data.pMessageIdName = "TEST-known-layer-bug";
  data.pMessage = "filtered";
  submit_message(context().instance(), VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT,
                 VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT, &data);
  EXPECT_EQ(log.count(), 0u) << log.summary();
  EXPECT_EQ(log.ignored_count(), 1u);
}

}  // namespace
}  // namespace tilelight
