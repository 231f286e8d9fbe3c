#pragma once
// 8-bit RGBA pictures drawn on the CPU: the tile-class picture, its legend text and the
// benchmarks' bar charts all draw on an Rgba8Canvas, and png.h encodes one as it is.

#include <array>
#include <cstdint>
#include <vector>

namespace tilelight {

// An 8-bit RGBA colour.
using Rgba8 = std::array<std::uint8_t, 4>;

// 8-bit RGBA pixels, rows top to bottom, tightly packed (the layout encode_png takes).
struct Rgba8Canvas {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<std::uint8_t> pixels;  // width * height * 4

  // A width x height canvas filled with `colour`.
  static Rgba8Canvas filled(std::uint32_t width, std::uint32_t height, Rgba8 colour);

  // Precondition: x < width, y < height (not checked: this is for inner loops and tests).
  Rgba8 pixel(std::uint32_t x, std::uint32_t y) const;

  // Sets one pixel; coordinates outside the canvas are ignored.
  void set_pixel(int x, int y, Rgba8 colour);

  // Fills the rectangle [x, x + w) x [y, y + h), clipped to the canvas; w or h <= 0 draws
  // nothing.
  void fill_rect(int x, int y, int w, int h, Rgba8 colour);
};

}  // namespace tilelight
