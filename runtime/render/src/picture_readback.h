#pragma once
// The renderer's targets read back as the picture library's images. The Vulkan layer returns
// plain float RGBA (it links no picture library); the renderer, whose public API hands out
// RgbaImage, converts here.

#include "tilelight/picture/rgba_image.h"
#include "tilelight/vulkan/readback.h"
#include "tilelight/vulkan/timeout.h"

#include <vulkan/vulkan.h>

namespace tilelight {

class Context;
class CommandPool;
class Image;

// The same pixels as an RgbaImage; moves them, no copy.
RgbaImage to_rgba_image(FloatRgba&& texels);

// read_image_float_rgba() as an RgbaImage, with its preconditions and errors.
RgbaImage read_image_rgba(const Context& context, const CommandPool& pool, const Image& image, VkImageLayout layout,
                          Seconds timeout = kDefaultGpuTimeout);

}  // namespace tilelight
