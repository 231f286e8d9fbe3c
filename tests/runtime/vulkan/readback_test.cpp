// Readback: exact values after vkCmdClearColorImage, row order after an upload, the decoders,
// and the preconditions that are checked.
#include "tilelight_testing/test_support.h"

#include "tilelight/vulkan/barriers.h"
#include "tilelight/vulkan/buffer.h"
#include "tilelight/vulkan/error.h"
#include "tilelight/vulkan/image.h"
#include "tilelight/vulkan/readback.h"
#include "tilelight/vulkan/submit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

namespace tilelight {
namespace {

using test::VulkanTest;

constexpr VkImageUsageFlags kTransfer = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;

Image make_image(Context& context, VkFormat format, std::uint32_t width, std::uint32_t height, const char* name) {
  return Image(context, {{width, height}, format, kTransfer, VK_SAMPLE_COUNT_1_BIT, VK_IMAGE_ASPECT_COLOR_BIT, name});
}

// Clears `image` (from UNDEFINED); it is left in TRANSFER_DST_OPTIMAL.
void clear(Context& context, CommandPool& pool, const Image& image, VkClearColorValue colour) {
  submit_and_wait(
      context, pool,
      [&](VkCommandBuffer cmd) {
        const VkImageSubresourceRange range = image.subresource_range();
        image_barrier(cmd, image.handle(), range, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                      {VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0},
                      {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT});
        vkCmdClearColorImage(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &colour, 1, &range);
      },
      "clearing " + image.name(), Seconds{30.0});
}

std::array<float, 4> pixel(const FloatRgba& image, std::uint32_t x, std::uint32_t y) {
  const std::size_t i = (std::size_t{y} * image.width + x) * 4;
  return {image.pixels[i], image.pixels[i + 1], image.pixels[i + 2], image.pixels[i + 3]};
}

void expect_every_pixel(const FloatRgba& pixels, std::array<float, 4> expected) {
  for (std::uint32_t y = 0; y < pixels.height; ++y) {
    for (std::uint32_t x = 0; x < pixels.width; ++x) {
      ASSERT_EQ(pixel(pixels, x, y), expected) << "at " << x << "," << y;
    }
  }
}

TEST_F(VulkanTest, ClearRgba8ReadsBackExactly) {
  const Image image = make_image(context(), VK_FORMAT_R8G8B8A8_UNORM, 13, 7, "lit result");
  // Multiples of 1/255 convert to UNORM8 exactly.
  clear(context(), pool(), image, {{51.0f / 255.0f, 102.0f / 255.0f, 1.0f, 0.0f}});
  const std::vector<std::byte> bytes = read_image_bytes(context(), pool(), image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
  ASSERT_EQ(bytes.size(), 13u * 7u * 4u);
  for (std::size_t i = 0; i < bytes.size(); i += 4) {
    ASSERT_EQ(std::to_integer<int>(bytes[i]), 51);
    ASSERT_EQ(std::to_integer<int>(bytes[i + 1]), 102);
    ASSERT_EQ(std::to_integer<int>(bytes[i + 2]), 255);
    ASSERT_EQ(std::to_integer<int>(bytes[i + 3]), 0);
  }
  const FloatRgba rgba = read_image_float_rgba(context(), pool(), image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
  expect_every_pixel(rgba, {51.0f / 255.0f, 102.0f / 255.0f, 1.0f, 0.0f});
}

TEST_F(VulkanTest, ClearFloatFormatsReadBackExactly) {
  // Values exact in half precision, including a negative one and one above 1.
  const std::array<float, 4> colour = {0.5f, -2.0f, 1024.0f, 0.125f};
  for (const VkFormat format : {VK_FORMAT_R16G16B16A16_SFLOAT, VK_FORMAT_R32G32B32A32_SFLOAT}) {
    const Image image = make_image(context(), format, 5, 3, "HDR target");
    clear(context(), pool(), image, {{colour[0], colour[1], colour[2], colour[3]}});
    expect_every_pixel(read_image_float_rgba(context(), pool(), image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL), colour);
  }
}

TEST_F(VulkanTest, Bgra8IsSwizzledToRgba) {
  const Image image = make_image(context(), VK_FORMAT_B8G8R8A8_UNORM, 2, 2, "bgra");
  clear(context(), pool(), image, {{1.0f, 0.0f, 51.0f / 255.0f, 1.0f}});
  expect_every_pixel(read_image_float_rgba(context(), pool(), image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL),
                     {1.0f, 0.0f, 51.0f / 255.0f, 1.0f});
}

TEST_F(VulkanTest, UploadedPatternComesBackInRowOrder) {
  constexpr std::uint32_t kWidth = 6;
  constexpr std::uint32_t kHeight = 4;
  const Image image = make_image(context(), VK_FORMAT_R8G8B8A8_UNORM, kWidth, kHeight, "pattern");
  Buffer upload(context(),
                {kWidth * kHeight * 4, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::HostUpload, "pattern upload"});
  const std::span<std::uint8_t> texels = upload.as<std::uint8_t>();
  for (std::uint32_t y = 0; y < kHeight; ++y) {
    for (std::uint32_t x = 0; x < kWidth; ++x) {
      std::uint8_t* t = &texels[(y * kWidth + x) * 4];
      t[0] = static_cast<std::uint8_t>(x * 10);
      t[1] = static_cast<std::uint8_t>(y * 20);
      t[2] = 7;
      t[3] = 255;
    }
  }
  submit_and_wait(
      context(), pool(),
      [&](VkCommandBuffer cmd) {
        image_barrier(cmd, image.handle(), image.subresource_range(), VK_IMAGE_LAYOUT_UNDEFINED,
                      VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, {VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0},
                      {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT});
        VkBufferImageCopy region{};
        region.imageSubresource = image.subresource_layers();
        region.imageExtent = {kWidth, kHeight, 1};
        vkCmdCopyBufferToImage(cmd, upload.handle(), image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        // Leave it as a sampled image would be, to test the layout round trip.
        image_barrier(cmd, image.handle(), image.subresource_range(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                      VK_IMAGE_LAYOUT_GENERAL, {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT},
                      {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT});
      },
      "uploading a pattern", Seconds{30.0});
  const FloatRgba rgba = read_image_float_rgba(context(), pool(), image, VK_IMAGE_LAYOUT_GENERAL);
  for (std::uint32_t y = 0; y < kHeight; ++y) {
    for (std::uint32_t x = 0; x < kWidth; ++x) {
      const std::array<float, 4> expected = {static_cast<float>(x * 10) / 255.0f, static_cast<float>(y * 20) / 255.0f,
                                             7.0f / 255.0f, 1.0f};
      ASSERT_EQ(pixel(rgba, x, y), expected) << "at " << x << "," << y;
    }
  }
  // A second readback from the same layout works: the first put the image back in GENERAL.
  EXPECT_EQ(read_image_float_rgba(context(), pool(), image, VK_IMAGE_LAYOUT_GENERAL).pixels, rgba.pixels);
}

TEST_F(VulkanTest, ReadbackPreconditionsAreChecked) {
  const Image msaa(context(), {{4, 4},
                               VK_FORMAT_R8G8B8A8_UNORM,
                               VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                               VK_SAMPLE_COUNT_4_BIT,
                               VK_IMAGE_ASPECT_COLOR_BIT,
                               "MSAA target"});
  try {
    read_image_bytes(context(), pool(), msaa, VK_IMAGE_LAYOUT_GENERAL);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "reading back MSAA target: the image has 4 samples; resolve it to a "
                 "single-sample image first");
  }
  const Image no_transfer(context(), {{4, 4},
                                      VK_FORMAT_R8G8B8A8_UNORM,
                                      VK_IMAGE_USAGE_SAMPLED_BIT,
                                      VK_SAMPLE_COUNT_1_BIT,
                                      VK_IMAGE_ASPECT_COLOR_BIT,
                                      "x"});
  EXPECT_THROW(read_image_bytes(context(), pool(), no_transfer, VK_IMAGE_LAYOUT_GENERAL), Error);
  const Image fresh = make_image(context(), VK_FORMAT_R8G8B8A8_UNORM, 4, 4, "fresh");
  EXPECT_THROW(read_image_bytes(context(), pool(), fresh, VK_IMAGE_LAYOUT_UNDEFINED), Error);
  const Image ids = make_image(context(), VK_FORMAT_R32_UINT, 4, 4, "tile IDs");
  EXPECT_THROW(read_image_float_rgba(context(), pool(), ids, VK_IMAGE_LAYOUT_GENERAL), Error);
}

TEST(Decode, HalfToFloat) {
  EXPECT_EQ(half_to_float(0x0000), 0.0f);
  EXPECT_TRUE(std::signbit(half_to_float(0x8000)));
  EXPECT_EQ(half_to_float(0x3c00), 1.0f);
  EXPECT_EQ(half_to_float(0xc000), -2.0f);
  EXPECT_EQ(half_to_float(0x7bff), 65504.0f);
  EXPECT_EQ(half_to_float(0x0001), std::ldexp(1.0f, -24));  // smallest subnormal
  EXPECT_EQ(half_to_float(0x03ff), std::ldexp(1023.0f, -24));
  EXPECT_EQ(half_to_float(0x7c00), std::numeric_limits<float>::infinity());
  EXPECT_TRUE(std::isnan(half_to_float(0x7e00)));
}

TEST(Decode, SingleChannelAndSizeMismatch) {
  const float values[] = {0.25f, -1.0f};
  std::array<std::byte, 8> bytes{};
  std::memcpy(bytes.data(), values, sizeof(values));
  const FloatRgba image = decode_rgba(VK_FORMAT_D32_SFLOAT, 2, 1, bytes);
  EXPECT_EQ(pixel(image, 0, 0), (std::array<float, 4>{0.25f, 0.0f, 0.0f, 1.0f}));
  EXPECT_EQ(pixel(image, 1, 0), (std::array<float, 4>{-1.0f, 0.0f, 0.0f, 1.0f}));
  EXPECT_THROW(decode_rgba(VK_FORMAT_R32_SFLOAT, 3, 1, bytes), Error);
  EXPECT_THROW(decode_rgba(VK_FORMAT_R32_UINT, 2, 1, bytes), Error);
}

}  // namespace
}  // namespace tilelight
