#include "tilelight/picture/png.h"

#include "tilelight/base/error.h"

#include <fmt/format.h>
#include <stb/stb_image_write.h>

#include <climits>
#include <cmath>
#include <new>
#include <utility>

namespace tilelight {
namespace {

struct EncodedPng {
  std::vector<std::uint8_t> bytes;
  bool out_of_memory = false;
};

// Called from inside stb (C code): no exception may cross it, so a failed allocation is
// recorded and reported once stb has returned.
void append_bytes(void* context, void* data, int size) noexcept {
  auto* out = static_cast<EncodedPng*>(context);
  if (out->out_of_memory) return;
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  try {
    out->bytes.insert(out->bytes.end(), bytes, bytes + size);
  } catch (const std::bad_alloc&) {
    out->out_of_memory = true;
  }
}

}  // namespace

std::vector<std::uint8_t> to_rgba8(const RgbaImage& image) {
  std::vector<std::uint8_t> out(image.pixels.size());
  for (std::size_t i = 0; i < image.pixels.size(); ++i) out[i] = to_unorm8(image.pixels[i]);
  return out;
}

std::vector<std::uint8_t> encode_png(std::uint32_t width, std::uint32_t height, std::span<const std::uint8_t> rgba) {
  const std::size_t expected = static_cast<std::size_t>(width) * height * 4;
  if (width == 0 || height == 0 || rgba.size() != expected) {
    throw Error(fmt::format("{}x{} RGBA needs {} bytes, got {}", width, height, expected, rgba.size()));
  }
  if (width > INT_MAX / 4 || height > INT_MAX) {
    throw Error(fmt::format("{}x{} is too large", width, height));
  }
  // Encoded in memory, so that file errors come from our own I/O with a precise reason (stb's
  // file writer reports only "failed").
  EncodedPng png;
  const int w = static_cast<int>(width);
  const int h = static_cast<int>(height);
  // stb fails only when its own allocation fails.
  if (stbi_write_png_to_func(&append_bytes, &png, w, h, 4, rgba.data(), w * 4) == 0 || png.out_of_memory) {
    throw Error(fmt::format("out of host memory while encoding {}x{}", width, height));
  }
  return std::move(png.bytes);
}

std::vector<std::uint8_t> encode_png(const RgbaImage& image) {
  return encode_png(image.width, image.height, to_rgba8(image));
}

}  // namespace tilelight
