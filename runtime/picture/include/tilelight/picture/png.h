#pragma once
// PNG encoding, in memory: the callers write the bytes atomically with their other outputs
// (tilelight/app/output_files.h), so a crashed or concurrent run never leaves a half-written
// image that a later comparison would read.

#include "tilelight/picture/rgba_image.h"

#include <cstdint>
#include <span>
#include <vector>

namespace tilelight {

// Float RGBA -> 8-bit RGBA, every channel through to_unorm8() (rgba_image.h). No gamma is
// applied (the values are written as they are).
std::vector<std::uint8_t> to_rgba8(const RgbaImage& image);

// The PNG file bytes of 8-bit RGBA pixels (rows top to bottom, width * height * 4 bytes).
// Throws tilelight::Error "<w>x<h> RGBA needs <n> bytes, got <m>", "<w>x<h> is too large" or
// "out of host memory while encoding <w>x<h>".
std::vector<std::uint8_t> encode_png(std::uint32_t width, std::uint32_t height, std::span<const std::uint8_t> rgba);

// encode_png() of to_rgba8(image).
std::vector<std::uint8_t> encode_png(const RgbaImage& image);

}  // namespace tilelight
