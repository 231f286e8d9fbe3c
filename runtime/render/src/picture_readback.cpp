#include "picture_readback.h"

#include <utility>

namespace tilelight {

RgbaImage to_rgba_image(FloatRgba&& texels) {
  RgbaImage image;
  image.width = texels.width;
  image.height = texels.height;
  image.pixels = std::move(texels.pixels);
  return image;
}

RgbaImage read_image_rgba(const Context& context, const CommandPool& pool, const Image& image, VkImageLayout layout,
                          Seconds timeout) {
  return to_rgba_image(read_image_float_rgba(context, pool, image, layout, timeout));
}

}  // namespace tilelight
