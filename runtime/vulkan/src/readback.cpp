#include "tilelight/vulkan/readback.h"

#include "tilelight/vulkan/barriers.h"
#include "tilelight/vulkan/buffer.h"
#include "tilelight/vulkan/commands.h"
#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"
#include "tilelight/vulkan/formats.h"
#include "tilelight/vulkan/image.h"
#include "tilelight/vulkan/submit.h"

#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <cstring>

namespace tilelight {
namespace {

template <typename T>
T load(const std::byte* p) {
  T value;
  std::memcpy(&value, p, sizeof(T));
  return value;
}

float unorm8(std::byte b) { return static_cast<float>(std::to_integer<unsigned>(b)) / 255.0f; }

}  // namespace

float half_to_float(std::uint16_t half) {
  const std::uint32_t sign = static_cast<std::uint32_t>(half & 0x8000u) << 16;
  const std::uint32_t exponent = (half >> 10) & 0x1fu;
  const std::uint32_t mantissa = half & 0x3ffu;
  if (exponent == 0) {
    // Zero or subnormal: mantissa * 2^-24, exact in float.
    const float magnitude = std::ldexp(static_cast<float>(mantissa), -24);
    return sign != 0 ? -magnitude : magnitude;
  }
  std::uint32_t bits = 0;
  if (exponent == 31) {
    bits = sign | 0x7f800000u | (mantissa << 13);  // infinity or NaN (payload kept)
  } else {
    bits = sign | ((exponent + 127 - 15) << 23) | (mantissa << 13);
  }
  return std::bit_cast<float>(bits);
}

bool can_decode_rgba(VkFormat format) {
  switch (format) {
    case VK_FORMAT_R8G8B8A8_UNORM:
    case VK_FORMAT_R8G8B8A8_SRGB:
    case VK_FORMAT_B8G8R8A8_UNORM:
    case VK_FORMAT_B8G8R8A8_SRGB:
    case VK_FORMAT_R16G16B16A16_SFLOAT:
    case VK_FORMAT_R32G32B32A32_SFLOAT:
    case VK_FORMAT_R32_SFLOAT:
    case VK_FORMAT_D32_SFLOAT: return true;
    default: return false;
  }
}

FloatRgba decode_rgba(VkFormat format, std::uint32_t width, std::uint32_t height, std::span<const std::byte> texels) {
  if (!can_decode_rgba(format)) {
    throw Error(fmt::format("cannot decode {} to float RGBA", format_name(format)));
  }
  const std::size_t count = static_cast<std::size_t>(width) * height;
  const std::size_t stride = texel_size(format);
  if (texels.size() != count * stride) {
    throw Error(fmt::format("{}x{} {} needs {} bytes, got {}", width, height, format_name(format), count * stride,
                            texels.size()));
  }
  FloatRgba out;
  out.width = width;
  out.height = height;
  out.pixels.resize(count * 4);
  for (std::size_t i = 0; i < count; ++i) {
    const std::byte* t = texels.data() + i * stride;
    float* p = out.pixels.data() + i * 4;
    switch (format) {
      case VK_FORMAT_R8G8B8A8_UNORM:
      case VK_FORMAT_R8G8B8A8_SRGB:
        for (std::size_t c = 0; c < 4; ++c) {
          p[c] = unorm8(t[c]);
        }
        break;
      case VK_FORMAT_B8G8R8A8_UNORM:
      case VK_FORMAT_B8G8R8A8_SRGB:
        p[0] = unorm8(t[2]);
        p[1] = unorm8(t[1]);
        p[2] = unorm8(t[0]);
        p[3] = unorm8(t[3]);
        break;
      case VK_FORMAT_R16G16B16A16_SFLOAT:
        for (std::size_t c = 0; c < 4; ++c) {
          p[c] = half_to_float(load<std::uint16_t>(t + 2 * c));
        }
        break;
      case VK_FORMAT_R32G32B32A32_SFLOAT: std::memcpy(p, t, 16); break;
      default:  // R32_SFLOAT, D32_SFLOAT
        p[0] = load<float>(t);
        p[1] = 0.0f;
        p[2] = 0.0f;
        p[3] = 1.0f;
        break;
    }
  }
  return out;
}

std::vector<std::byte> read_image_bytes(const Context& context, const CommandPool& pool, const Image& image,
                                        VkImageLayout layout, Seconds timeout) {
  const std::string stage = fmt::format("reading back {}", image.name());
  if (image.samples() != VK_SAMPLE_COUNT_1_BIT) {
    throw Error(fmt::format("{}: the image has {} samples; resolve it to a single-sample image first", stage,
                            static_cast<unsigned>(image.samples())));
  }
  if ((image.usage() & VK_IMAGE_USAGE_TRANSFER_SRC_BIT) == 0) {
    throw Error(fmt::format("{}: the image was created without TRANSFER_SRC usage", stage));
  }
  if (layout == VK_IMAGE_LAYOUT_UNDEFINED) {
    throw Error(fmt::format("{}: the image is in layout UNDEFINED (its contents are undefined)", stage));
  }
  const std::uint32_t stride = texel_size(image.format());
  if (stride == 0) {
    throw Error(fmt::format("{}: unknown texel size of {}", stage, format_name(image.format())));
  }
  const VkExtent2D extent = image.extent();
  const VkDeviceSize size = VkDeviceSize{extent.width} * extent.height * stride;
  Buffer staging(context, {size, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::HostReadback,
                           fmt::format("readback of {}", image.name())});

  auto record = [&](VkCommandBuffer cmd) {
    const VkImageSubresourceRange range = image.subresource_range();
    // Earlier submits may have written the image in any stage.
    image_barrier(cmd, image.handle(), range, layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                  {VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_MEMORY_WRITE_BIT},
                  {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT});
    VkBufferImageCopy region{};
    region.bufferOffset = 0;
    region.bufferRowLength = 0;  // tightly packed
    region.bufferImageHeight = 0;
    region.imageSubresource = image.subresource_layers();
    region.imageExtent = {extent.width, extent.height, 1};
    vkCmdCopyImageToBuffer(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging.handle(), 1, &region);
    // Back to the caller's layout, so that their layout tracking stays true.
    image_barrier(cmd, image.handle(), range, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, layout,
                  {VK_PIPELINE_STAGE_TRANSFER_BIT, 0},
                  {VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT});
    buffer_barrier(cmd, staging.handle(), {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT},
                   {VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT});
  };
  try {
    submit_and_wait(context, pool, record, stage, timeout);
  } catch (const TimeoutError&) {
    // The copy may still be running: keep its destination alive.
    [[maybe_unused]] auto* leaked = new Buffer(std::move(staging));
    throw;
  }

  std::vector<std::byte> bytes(static_cast<std::size_t>(size));
  staging.read(bytes);
  return bytes;
}

FloatRgba read_image_float_rgba(const Context& context, const CommandPool& pool, const Image& image,
                                VkImageLayout layout, Seconds timeout) {
  if (!can_decode_rgba(image.format())) {
    throw Error(
        fmt::format("reading back {}: cannot decode {} to float RGBA", image.name(), format_name(image.format())));
  }
  const std::vector<std::byte> bytes = read_image_bytes(context, pool, image, layout, timeout);
  return decode_rgba(image.format(), image.extent().width, image.extent().height, bytes);
}

}  // namespace tilelight
