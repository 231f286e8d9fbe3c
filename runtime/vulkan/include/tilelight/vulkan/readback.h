#pragma once
// Copying images back to the host: every test compares pixels, and every image the demo writes
// comes this way. This is where texels in a Vulkan format become plain float RGBA; the layers
// above turn that into their own image types (the renderer into the picture library's
// RgbaImage), so the Vulkan layer needs no image or PNG library.

#include "tilelight/vulkan/timeout.h"

#include <vulkan/vulkan.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace tilelight {

class Context;
class CommandPool;
class Image;

// Float RGBA texels, rows top to bottom, tightly packed: pixels[(y * width + x) * 4 + channel].
struct FloatRgba {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<float> pixels;  // width * height * 4
};

// Copies `image` into a host buffer and returns its texels as stored (tightly packed rows of
// texel_size(format) bytes). Preconditions, checked (tilelight::Error): the image is
// single-sample (resolve MSAA images first), has TRANSFER_SRC usage, and `layout` is its
// current layout, not UNDEFINED. All work that writes it must have been submitted before this
// call: the copy waits for ALL_COMMANDS of earlier submits. Afterwards the image is back in
// `layout`. Waits at most `timeout` (TimeoutError).
std::vector<std::byte> read_image_bytes(const Context& context, const CommandPool& pool, const Image& image,
                                        VkImageLayout layout, Seconds timeout = kDefaultGpuTimeout);

// read_image_bytes() decoded by decode_rgba(). Also throws tilelight::Error, before copying,
// when can_decode_rgba() does not know the image's format.
FloatRgba read_image_float_rgba(const Context& context, const CommandPool& pool, const Image& image,
                                VkImageLayout layout, Seconds timeout = kDefaultGpuTimeout);

// Whether decode_rgba() knows `format`: R8G8B8A8/B8G8R8A8 UNORM and SRGB, R16G16B16A16_SFLOAT,
// R32G32B32A32_SFLOAT, R32_SFLOAT and D32_SFLOAT (single channel -> (v, 0, 0, 1)).
bool can_decode_rgba(VkFormat format);

// Converts tightly packed texels to float RGBA. 8-bit formats give value / 255 of the stored
// byte: SRGB values are NOT linearised, so a PNG written from them shows what the image holds.
// B8G8R8A8 is swizzled to RGBA. Throws tilelight::Error for other formats or a size mismatch.
FloatRgba decode_rgba(VkFormat format, std::uint32_t width, std::uint32_t height, std::span<const std::byte> texels);

// IEEE half to float, including subnormals, infinities and NaN.
float half_to_float(std::uint16_t half);

}  // namespace tilelight
