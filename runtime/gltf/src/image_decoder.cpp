#include "image_decoder.h"

#include "tilelight/base/error.h"

#include <fmt/format.h>

// stb_image (Debian's libstb-dev) compiled into this file alone, and static: the sanitizer
// build and the glTF fuzz target instrument the decoder that reads the file's bytes, and its
// functions cannot clash with libstb.so's, which the tests link. PNG and JPEG only (the two
// formats core glTF allows), from memory only.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_NO_STDIO
#include <stb/stb_image.h>

#include <climits>
#include <cstring>
#include <memory>

namespace tilelight::gltf_detail {
namespace {

struct StbiFree {
  void operator()(stbi_uc* pixels) const { stbi_image_free(pixels); }
};

std::string failure_reason() {
  const char* reason = stbi_failure_reason();
  return reason != nullptr ? reason : "unknown reason";
}

}  // namespace

DecodedImage decode_image(std::span<const std::uint8_t> bytes, const std::string& what) {
  if (bytes.empty()) throw Error(what + ": the image has no bytes");
  if (bytes.size() > static_cast<std::size_t>(INT_MAX)) throw Error(what + ": the image is larger than 2 GiB");
  const int size = static_cast<int>(bytes.size());
  int width = 0, height = 0, channels = 0;
  if (stbi_info_from_memory(bytes.data(), size, &width, &height, &channels) == 0) {
    throw Error(fmt::format("{}: not a PNG or JPEG image this loader can decode ({})", what, failure_reason()));
  }
  if (width <= 0 || height <= 0 || static_cast<std::uint32_t>(width) > kMaxImageSide ||
      static_cast<std::uint32_t>(height) > kMaxImageSide) {
    throw Error(fmt::format("{}: {}x{} pixels; at most {} a side are loaded", what, width, height, kMaxImageSide));
  }
  std::unique_ptr<stbi_uc, StbiFree> pixels(stbi_load_from_memory(bytes.data(), size, &width, &height, &channels, 4));
  if (!pixels) throw Error(fmt::format("{}: the image is corrupt or truncated ({})", what, failure_reason()));
  DecodedImage image;
  image.width = static_cast<std::uint32_t>(width);
  image.height = static_cast<std::uint32_t>(height);
  image.rgba.resize(std::size_t{image.width} * image.height * 4);
  std::memcpy(image.rgba.data(), pixels.get(), image.rgba.size());
  return image;
}

}  // namespace tilelight::gltf_detail
