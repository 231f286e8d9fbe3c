// MSAA choice: 2x where the device has it, else 4x; explicit requests the device lacks fail, and
// so does 1x (the G-buffer is always multisampled).
#include "tilelight/context.h"
#include "tilelight/error.h"
#include "tilelight/msaa.h"

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
  EXPECT_EQ(error_of(0, 0),
            "the device offers no multisampled G-buffer (colour and depth attachments that can also be sampled "
            "with 2 or more samples)");
}

TEST(Msaa, ExplicitRequestNamesValueAndSupportedCounts) {
  EXPECT_EQ(choose_msaa(kFour, 4), VK_SAMPLE_COUNT_4_BIT);
  EXPECT_EQ(error_of(kFour, 1),
            "MSAA 1x is not available: the G-buffer is multisampled by design (the lighting and the "
            "classification read it as sampler2DMS, and MSAA_EDGE is one of the tile features); supported for "
            "the G-buffer: 4x");
  EXPECT_EQ(error_of(kFour, 2), "MSAA 2x is not supported by this device (supported for the G-buffer: 4x)");
  EXPECT_EQ(error_of(kFour, 3),
            "MSAA 3x is not a sample count (use 0 for auto, or 2, 4, 8, 16, 32, 64; "
            "supported for the G-buffer: 4x)");
  EXPECT_NE(error_of(kFour, 128).find("not a sample count"), std::string::npos);
}

TEST(Msaa, SupportedCountsNeedEveryUse) {
  DeviceLimits limits;
  limits.framebuffer_color_samples = kOneFour | VK_SAMPLE_COUNT_2_BIT;
  limits.framebuffer_depth_samples = kOneFour | VK_SAMPLE_COUNT_2_BIT;
  limits.sampled_color_samples = kOneFour | VK_SAMPLE_COUNT_2_BIT;
  limits.sampled_depth_samples = kOneFour;  // no 2x for sampled depth
  EXPECT_EQ(msaa_supported_counts(limits), kFour);  // and never 1x
}

TEST(MsaaOnLavapipe, AutoIsFourAndTwoOrEightFail) {
  Context context;
  EXPECT_EQ(context.msaa_counts(), kFour);  // lavapipe: 1x and 4x only, and 1x is no G-buffer
  EXPECT_EQ(context.choose_msaa(0), VK_SAMPLE_COUNT_4_BIT);
  EXPECT_EQ(context.choose_msaa(4), VK_SAMPLE_COUNT_4_BIT);
  EXPECT_THROW(context.choose_msaa(2), Error);
  try {
    context.choose_msaa(8);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "MSAA 8x is not supported by this device (supported for the G-buffer: 4x)");
  }
}

}  // namespace
}  // namespace tilelight
