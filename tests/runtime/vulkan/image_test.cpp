// Images: creation with a clear reason when the device lacks a combination; samplers.
#include "tilelight_testing/test_support.h"

#include "tilelight/vulkan/error.h"
#include "tilelight/vulkan/image.h"
#include "tilelight/vulkan/sampler.h"

#include <gtest/gtest.h>

namespace tilelight {
namespace {

using test::VulkanTest;

TEST_F(VulkanTest, MultisampledGBufferTargetsAndDepth) {
  const VkSampleCountFlagBits samples = context().choose_msaa(0);
  Image rt1(context(), {{64, 32},
                        VK_FORMAT_R16G16B16A16_SFLOAT,
                        VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                        samples,
                        VK_IMAGE_ASPECT_COLOR_BIT,
                        "G-buffer RT1"});
  Image depth(context(), {{64, 32},
                          VK_FORMAT_D32_SFLOAT,
                          VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                          samples,
                          VK_IMAGE_ASPECT_DEPTH_BIT,
                          "G-buffer depth"});
  EXPECT_NE(rt1.handle(), VK_NULL_HANDLE);
  EXPECT_NE(rt1.view(), VK_NULL_HANDLE);
  EXPECT_EQ(rt1.samples(), samples);
  EXPECT_EQ(depth.subresource_range().aspectMask, VK_IMAGE_ASPECT_DEPTH_BIT);
  EXPECT_EQ(depth.extent().width, 64u);
}

TEST_F(VulkanTest, UnsupportedSampleCountSaysWhich) {
  try {
    Image image(context(), {{16, 16},
                            VK_FORMAT_R8G8B8A8_UNORM,
                            VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT,
                            VK_SAMPLE_COUNT_8_BIT,
                            VK_IMAGE_ASPECT_COLOR_BIT,
                            "lit result"});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "image lit result: VK_FORMAT_R8G8B8A8_UNORM with usage 0x10 does not support 8x "
                 "samples (supported: 1x, 4x)");
  }
}

TEST_F(VulkanTest, UnsupportedFormatUsageNamesTheFormat) {
  try {
    Image image(context(), {{16, 16},
                            VK_FORMAT_R8G8B8A8_UNORM,
                            VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                            VK_SAMPLE_COUNT_1_BIT,
                            VK_IMAGE_ASPECT_COLOR_BIT,
                            "bad depth"});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("image bad depth: VK_FORMAT_R8G8B8A8_UNORM is not "
                                         "supported for usage 0x20"),
              std::string::npos)
        << e.what();
  }
}

TEST_F(VulkanTest, EmptyExtentIsRejected) {
  EXPECT_THROW(Image(context(), {{0, 16},
                                 VK_FORMAT_R8G8B8A8_UNORM,
                                 VK_IMAGE_USAGE_SAMPLED_BIT,
                                 VK_SAMPLE_COUNT_1_BIT,
                                 VK_IMAGE_ASPECT_COLOR_BIT,
                                 "empty"}),
               Error);
}

TEST_F(VulkanTest, MoveAssignReleasesTheOldImage) {
  Image a(context(), {{8, 8},
                      VK_FORMAT_R8G8B8A8_UNORM,
                      VK_IMAGE_USAGE_SAMPLED_BIT,
                      VK_SAMPLE_COUNT_1_BIT,
                      VK_IMAGE_ASPECT_COLOR_BIT,
                      "a"});
  Image b(context(), {{4, 4},
                      VK_FORMAT_R8G8B8A8_UNORM,
                      VK_IMAGE_USAGE_SAMPLED_BIT,
                      VK_SAMPLE_COUNT_1_BIT,
                      VK_IMAGE_ASPECT_COLOR_BIT,
                      "b"});
  a = std::move(b);
  EXPECT_EQ(a.extent().width, 4u);
  EXPECT_EQ(a.name(), "b");
  EXPECT_EQ(b.handle(), VK_NULL_HANDLE);
}

TEST_F(VulkanTest, ShadowComparisonSampler) {
  SamplerDesc desc;
  desc.mag_filter = desc.min_filter = VK_FILTER_LINEAR;
  desc.address_u = desc.address_v = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER;
  desc.compare = true;
  desc.name = "shadow map sampler";
  Sampler sampler(context(), desc);
  EXPECT_NE(sampler.handle(), VK_NULL_HANDLE);
  EXPECT_EQ(sampler.name(), "shadow map sampler");
}

}  // namespace
}  // namespace tilelight
