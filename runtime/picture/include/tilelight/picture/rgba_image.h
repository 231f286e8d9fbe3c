#pragma once
// The picture library's image: float RGBA as the renderer reads its targets back (the Vulkan
// layer's readback converts texels into it), kept free of Vulkan so that PNG output, the
// tile-class picture and the benchmarks' charts need no GPU library.

#include <array>
#include <cstdint>
#include <vector>

namespace tilelight {

// Float RGBA pixels, rows top to bottom, tightly packed.
struct RgbaImage {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<float> pixels;  // width * height * 4

  // Precondition: x < width, y < height.
  std::array<float, 4> at(std::uint32_t x, std::uint32_t y) const;
};

}  // namespace tilelight
