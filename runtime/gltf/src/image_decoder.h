#pragma once
// A glTF image's encoded bytes (PNG or JPEG) decoded to RGBA8.

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace tilelight::gltf_detail {

// The largest width or height decoded: larger images are refused before any pixel is decoded,
// so a hostile header cannot make the loader allocate gigabytes.
inline constexpr std::uint32_t kMaxImageSide = 8192;

struct DecodedImage {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4, rows from the top; grey and RGB get alpha 255
};

// Throws tilelight::Error starting with `what` ("images[2]") when the bytes are not a PNG or
// JPEG image, are truncated or corrupt, or the image is larger than kMaxImageSide.
DecodedImage decode_image(std::span<const std::uint8_t> bytes, const std::string& what);

}  // namespace tilelight::gltf_detail
