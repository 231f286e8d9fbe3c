#include "tilelight/picture/rgba8_canvas.h"

#include <algorithm>
#include <cstddef>

namespace tilelight {

Rgba8Canvas Rgba8Canvas::filled(std::uint32_t width, std::uint32_t height, Rgba8 colour) {
  Rgba8Canvas canvas;
  canvas.width = width;
  canvas.height = height;
  // Build one row, then append copies of it: every byte is written once (no zero fill
  // first) and in large blocks, which matters for 4K pictures (~40 MB).
  std::vector<std::uint8_t> row(static_cast<std::size_t>(width) * 4);
  for (std::size_t i = 0; i < row.size(); ++i) row[i] = colour[i % 4];
  canvas.pixels.reserve(row.size() * height);
  for (std::uint32_t y = 0; y < height; ++y) {
    canvas.pixels.insert(canvas.pixels.end(), row.begin(), row.end());
  }
  return canvas;
}

Rgba8 Rgba8Canvas::pixel(std::uint32_t x, std::uint32_t y) const {
  const std::size_t offset = (static_cast<std::size_t>(y) * width + x) * 4;
  return {pixels[offset], pixels[offset + 1], pixels[offset + 2], pixels[offset + 3]};
}

void Rgba8Canvas::set_pixel(int x, int y, Rgba8 colour) { fill_rect(x, y, 1, 1, colour); }

void Rgba8Canvas::fill_rect(int x, int y, int w, int h, Rgba8 colour) {
  // Clip in 64 bits so that huge rectangles or offsets cannot overflow.
  const long long x0 = std::max<long long>(x, 0);
  const long long y0 = std::max<long long>(y, 0);
  const long long x1 = std::min<long long>(static_cast<long long>(x) + w, width);
  const long long y1 = std::min<long long>(static_cast<long long>(y) + h, height);
  for (long long row = y0; row < y1; ++row) {
    for (long long column = x0; column < x1; ++column) {
      const auto offset = static_cast<std::size_t>((row * width + column) * 4);
      std::copy(colour.begin(), colour.end(), pixels.begin() + static_cast<std::ptrdiff_t>(offset));
    }
  }
}

}  // namespace tilelight
