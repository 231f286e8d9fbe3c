#pragma once
// PNG files for the tests: pictures a human looks at after a run, and the encoder checked end
// to end through a file. The products never write one PNG on its own: tilelight and the sweep
// stage encode_png() bytes with their other outputs (tilelight/app/output_files.h), so these
// live here rather than in the picture library.

#include "tilelight/picture/rgba_image.h"

#include <cstdint>
#include <filesystem>
#include <span>

namespace tilelight::test {

// Writes `image` (through to_rgba8) as an RGBA PNG at `path`, atomically
// (tilelight/base/atomic_write.h). The parent folder must exist. Throws tilelight::Error
// "cannot write PNG <path>: <reason>"; no temporary file is left behind either way.
void write_png(const std::filesystem::path& path, const RgbaImage& image);

// The same for 8-bit RGBA pixels (rows top to bottom, width * height * 4 bytes).
void write_png_rgba8(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
                     std::span<const std::uint8_t> rgba);

}  // namespace tilelight::test
