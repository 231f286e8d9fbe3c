#pragma once
// The mip chain of a base colour texture, made on the CPU: the same on every device and
// driver (no dependence on linear-filter blits of sRGB formats), and testable without Vulkan.

#include "tilelight/scene/scene.h"

#include <cstdint>
#include <vector>

namespace tilelight {

struct TextureMip {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<std::uint8_t> rgba;  // sRGB-encoded like Texture::rgba
};

// Every level down to 1x1: level 0 is the texture's own pixels; each next level halves each
// side (rounding down, at least 1 texel), every texel the mean of the up to 2x2 texels it covers
// in the level above, taken in linear light for the colour channels and directly for alpha,
// then encoded to sRGB 8-bit with rounding. Precondition: width, height > 0 and rgba holds
// width * height * 4 bytes.
std::vector<TextureMip> srgb_mip_chain(const Texture& texture);

// 1 + floor(log2(max(width, height))): the number of levels srgb_mip_chain makes.
std::uint32_t mip_level_count(std::uint32_t width, std::uint32_t height);

}  // namespace tilelight
