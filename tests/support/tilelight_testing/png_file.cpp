#include "tilelight_testing/png_file.h"

#include "tilelight/base/atomic_write.h"
#include "tilelight/base/error.h"
#include "tilelight/picture/png.h"

#include <fmt/format.h>

namespace tilelight::test {

void write_png(const std::filesystem::path& path, const RgbaImage& image) {
  write_png_rgba8(path, image.width, image.height, to_rgba8(image));
}

void write_png_rgba8(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
                     std::span<const std::uint8_t> rgba) {
  try {
    write_file_atomically(path, encode_png(width, height, rgba));
  } catch (const Error& e) {
    throw Error(fmt::format("cannot write PNG {}: {}", path.string(), e.what()));
  }
}

}  // namespace tilelight::test
