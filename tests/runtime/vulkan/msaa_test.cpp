// MSAA choice: 2x where the device has it, else 4x, else 1x; 1x on request; explicit requests
// the device lacks fail.
#include "tilelight/vulkan/msaa.h"
#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <gtest/gtest.h>

namespace tilelight {
namespace {

constexpr VkSampleCountFlags kOneFour = VK_SAMPLE_COUNT_1_BIT | VK_SAMPLE_COUNT_4_BIT;
constexpr VkSampleCountFlags kFour = VK_SAMPLE_COUNT_4_BIT;

std::string error_of(VkSampleCountFlags supported, std::uint32_t requested) {
  try {
    choose_msaa(supported, requested);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(Msaa, AutoPrefersTwoThenFourThenMore) {
  EXPECT_EQ(choose_msaa(kFour | VK_SAMPLE_COUNT_2_BIT | VK_SAMPLE_COUNT_8_BIT, 0), VK_SAMPLE_COUNT_2_BIT);
  EXPECT_EQ(choose_msaa(kFour | VK_SAMPLE_COUNT_8_BIT, 0), VK_SAMPLE_COUNT_4_BIT);
  EXPECT_EQ(choose_msaa(VK_SAMPLE_COUNT_8_BIT, 0), VK_SAMPLE_COUNT_8_BIT);
  EXPECT_EQ(choose_msaa(VK_SAMPLE_COUNT_1_BIT, 0), VK_SAMPLE_COUNT_1_BIT);
}

TEST(Msaa, ExplicitRequestNamesValueAndSupportedCounts) {
  EXPECT_EQ(choose_msaa(kOneFour, 4), VK_SAMPLE_COUNT_4_BIT);
  EXPECT_EQ(choose_msaa(kOneFour, 1), VK_SAMPLE_COUNT_1_BIT);
  EXPECT_EQ(error_of(kOneFour, 2), "MSAA 2x is not supported by this device (supported for the G-buffer: 1x, 4x)");
  EXPECT_EQ(error_of(kOneFour, 3),
            "MSAA 3x is not a sample count (use 0 for auto, or 1, 2, 4, 8, 16, 32, 64; "
            "supported for the G-buffer: 1x, 4x)");
  EXPECT_NE(error_of(kOneFour, 128).find("not a sample count"), std::string::npos);
}

TEST(Msaa, SupportedCountsNeedEveryUse) {
  DeviceLimits limits;
  limits.framebuffer_color_samples = kOneFour | VK_SAMPLE_COUNT_2_BIT;
  limits.framebuffer_depth_samples = kOneFour | VK_SAMPLE_COUNT_2_BIT;
  limits.sampled_color_samples = kOneFour | VK_SAMPLE_COUNT_2_BIT;
  limits.sampled_depth_samples = kOneFour;  // no 2x for sampled depth
  EXPECT_EQ(msaa_supported_counts(limits), kOneFour);
}

TEST(MsaaOnLavapipe, AutoIsFourAndTwoOrEightFail) {
  Context context;
  EXPECT_EQ(context.msaa_counts(), kOneFour);  // lavapipe: 1x and 4x only
  EXPECT_EQ(context.choose_msaa(0), VK_SAMPLE_COUNT_4_BIT);
  EXPECT_EQ(context.choose_msaa(1), VK_SAMPLE_COUNT_1_BIT);
  EXPECT_EQ(context.choose_msaa(4), VK_SAMPLE_COUNT_4_BIT);
  EXPECT_THROW(context.choose_msaa(2), Error);
  try {
    context.choose_msaa(8);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "MSAA 8x is not supported by this device (supported for the G-buffer: 1x, 4x)");
  }
}

}  // namespace
}  // namespace tilelight
