#include "tilelight/picture/rgba_image.h"

#include <cstddef>

namespace tilelight {

std::array<float, 4> RgbaImage::at(std::uint32_t x, std::uint32_t y) const {
  const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 4;
  return {pixels[i], pixels[i + 1], pixels[i + 2], pixels[i + 3]};
}

}  // namespace tilelight
