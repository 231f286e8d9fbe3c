#pragma once
// Whole files as bytes, for the .gltf/.glb itself, its external buffers and its images.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace tilelight::gltf_detail {

// The most bytes one file may have (2 GiB: tinygltf takes sizes as unsigned int).
inline constexpr std::uint64_t kMaxFileBytes = std::uint64_t{1} << 31;

// Reads the whole of `path`. Throws tilelight::Error starting with `what` when it is a folder,
// cannot be opened or read, or is larger than kMaxFileBytes.
std::vector<std::uint8_t> read_file(const std::filesystem::path& path, const std::string& what);

}  // namespace tilelight::gltf_detail
