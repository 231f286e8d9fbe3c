#pragma once
// The picture library's image: float RGBA as the renderer reads its targets back (the renderer
// moves the Vulkan layer's plain readback into it), kept free of Vulkan so that PNG output, the
// tile-class picture and the benchmarks' charts need no GPU library.

#include <array>
#include <cmath>
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

// One channel as 8 bits, the one conversion every picture uses: clamp to [0, 1], scale by 255
// (in float), round to nearest with halves away from zero; NaN -> 0. No gamma.
inline std::uint8_t to_unorm8(float v) {
  const float clamped = std::isnan(v) ? 0.0f : std::fmin(std::fmax(v, 0.0f), 1.0f);
  return static_cast<std::uint8_t>(std::lround(clamped * 255.0f));
}

}  // namespace tilelight
