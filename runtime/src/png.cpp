#include "tilelight/png.h"

#include "tilelight/error.h"

#include <fmt/format.h>
#include <stb/stb_image_write.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <new>
#include <system_error>

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

// Writes `bytes` to `path` and closes it, reporting the OS reason on failure.
void write_file(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes) {
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (file == nullptr) {
    throw Error(fmt::format("cannot create {}: {}", path.string(), std::strerror(errno)));
  }
  const std::size_t written = std::fwrite(bytes.data(), 1, bytes.size(), file);
  const int write_errno = errno;
  // fclose flushes; a full disk may only show up here.
  const bool closed = std::fclose(file) == 0;
  if (written != bytes.size() || !closed) {
    const int reason = written != bytes.size() ? write_errno : errno;
    throw Error(fmt::format("cannot write {}: {}", path.string(), std::strerror(reason)));
  }
}

}  // namespace

std::vector<std::uint8_t> to_rgba8(const RgbaImage& image) {
  std::vector<std::uint8_t> out(image.pixels.size());
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    const float v = image.pixels[i];
    const float clamped = std::isnan(v) ? 0.0f : std::fmin(std::fmax(v, 0.0f), 1.0f);
    out[i] = static_cast<std::uint8_t>(std::lround(clamped * 255.0f));
  }
  return out;
}

void write_png(const std::filesystem::path& path, const RgbaImage& image) {
  write_png_rgba8(path, image.width, image.height, to_rgba8(image));
}

void write_png_rgba8(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
                     std::span<const std::uint8_t> rgba) {
  const std::size_t expected = static_cast<std::size_t>(width) * height * 4;
  if (width == 0 || height == 0 || rgba.size() != expected) {
    throw Error(fmt::format("cannot write PNG {}: {}x{} RGBA needs {} bytes, got {}", path.string(),
                            width, height, expected, rgba.size()));
  }
  if (width > INT_MAX / 4 || height > INT_MAX) {
    throw Error(
        fmt::format("cannot write PNG {}: {}x{} is too large", path.string(), width, height));
  }

  // Encode in memory, so that file errors come from our own I/O with a precise reason (stb's
  // file writer reports only "failed").
  EncodedPng png;
  const int w = static_cast<int>(width);
  const int h = static_cast<int>(height);
  // stb fails only when its own allocation fails.
  if (stbi_write_png_to_func(&append_bytes, &png, w, h, 4, rgba.data(), w * 4) == 0 || png.out_of_memory) {
    throw Error(fmt::format("cannot write PNG {}: out of host memory while encoding {}x{}", path.string(), width,
                            height));
  }
  const std::vector<std::uint8_t>& encoded = png.bytes;

  std::filesystem::path temporary = path;
  temporary += fmt::format(".tmp-{}", static_cast<long>(::getpid()));
  try {
    write_file(temporary, encoded);
  } catch (const Error& e) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw Error(fmt::format("cannot write PNG {}: {}", path.string(), e.what()));
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw Error(fmt::format("cannot write PNG {}: renaming {} failed: {}", path.string(),
                            temporary.string(), ec.message()));
  }
}

}  // namespace tilelight
