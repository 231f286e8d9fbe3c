#include "tilelight/scene/texture_mips.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace tilelight {
namespace {

float srgb_to_linear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

float linear_to_srgb(float c) { return c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f; }

const std::array<float, 256>& linear_of_byte() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (std::size_t i = 0; i < t.size(); ++i) t[i] = srgb_to_linear(static_cast<float>(i) / 255.0f);
    return t;
  }();
  return table;
}

std::uint8_t to_byte(float unit) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(unit, 0.0f, 1.0f) * 255.0f));
}

TextureMip half_of(const TextureMip& above) {
  TextureMip mip;
  mip.width = std::max(1u, above.width / 2);
  mip.height = std::max(1u, above.height / 2);
  mip.rgba.resize(std::size_t{mip.width} * mip.height * 4);
  const std::array<float, 256>& linear = linear_of_byte();
  for (std::uint32_t y = 0; y < mip.height; ++y) {
    for (std::uint32_t x = 0; x < mip.width; ++x) {
      // The texels of the level above this one covers: 2x2, or fewer along a side of 1.
      const std::uint32_t x0 = std::min(2 * x, above.width - 1), x1 = std::min(2 * x + 1, above.width - 1);
      const std::uint32_t y0 = std::min(2 * y, above.height - 1), y1 = std::min(2 * y + 1, above.height - 1);
      std::array<float, 4> sum{};
      for (const std::uint32_t sy : {y0, y1}) {
        for (const std::uint32_t sx : {x0, x1}) {
          const std::uint8_t* texel = &above.rgba[(std::size_t{sy} * above.width + sx) * 4];
          for (int c = 0; c < 3; ++c) sum[c] += linear[texel[c]];
          sum[3] += static_cast<float>(texel[3]) / 255.0f;
        }
      }
      std::uint8_t* out = &mip.rgba[(std::size_t{y} * mip.width + x) * 4];
      for (int c = 0; c < 3; ++c) out[c] = to_byte(linear_to_srgb(sum[c] / 4.0f));
      out[3] = to_byte(sum[3] / 4.0f);
    }
  }
  return mip;
}

}  // namespace

std::uint32_t mip_level_count(std::uint32_t width, std::uint32_t height) {
  std::uint32_t levels = 1;
  for (std::uint32_t side = std::max(width, height); side > 1; side /= 2) ++levels;
  return levels;
}

std::vector<TextureMip> srgb_mip_chain(const Texture& texture) {
  std::vector<TextureMip> chain;
  chain.reserve(mip_level_count(texture.width, texture.height));
  chain.push_back({texture.width, texture.height, texture.rgba});
  while (chain.back().width > 1 || chain.back().height > 1) chain.push_back(half_of(chain.back()));
  return chain;
}

}  // namespace tilelight
