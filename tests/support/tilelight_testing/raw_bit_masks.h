// raw_bit_masks.h - Split/Second's raw bits as plain masks, for tests that read the classifier's
// bytes (raw IDs straight from the GPU, std::uint8_t) bit by bit. The generated raw_bit::
// constants are shadergen::RawBits, which combine with raw IDs only, so that an optimised bit
// cannot stand in for one; a byte is no RawId, and these say once that they are the same bits.
#pragma once

#include <split_second_shaders.h>

#include <cstdint>

namespace tilelight::raw_bit_masks {

inline constexpr std::uint32_t SHADOW_SOLID = split_second::raw_bit::SHADOW_SOLID.value();
inline constexpr std::uint32_t SHADOW_SOFT = split_second::raw_bit::SHADOW_SOFT.value();
inline constexpr std::uint32_t SHADOW_FADE = split_second::raw_bit::SHADOW_FADE.value();
inline constexpr std::uint32_t LIGHT_SCATTERING = split_second::raw_bit::LIGHT_SCATTERING.value();
inline constexpr std::uint32_t MSAA_EDGE = split_second::raw_bit::MSAA_EDGE.value();
inline constexpr std::uint32_t SKY = split_second::raw_bit::SKY.value();
inline constexpr std::uint32_t SUN_LIGHT = split_second::raw_bit::SUN_LIGHT.value();

}  // namespace tilelight::raw_bit_masks
