#pragma once
// Whole files as bytes, for the .gltf/.glb itself, its external buffers and its images: the
// project's one reader (common/whole_file, <whole_file/whole_file.h>) in the loader's words.

#include <whole_file/whole_file.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace tilelight::gltf_detail {

// The most bytes one file may have (2 GiB: tinygltf takes sizes as unsigned int).
inline constexpr std::uint64_t kMaxFileBytes = std::uint64_t{1} << 31;

// A failed read as the loader words it, starting with `what`: "<what>: is a folder, not a
// file", "<what>: cannot open: <reason>", "<what>: read failed: <reason>" or "<what>: <n>
// bytes, more than this loader reads (<kMaxFileBytes>)".
std::string describe_read_failure(const whole_file::Failure& failure, const std::string& what);

// Reads the whole of `path`, at most kMaxFileBytes. Throws tilelight::Error worded by
// describe_read_failure().
std::vector<std::uint8_t> read_file(const std::filesystem::path& path, const std::string& what);

}  // namespace tilelight::gltf_detail
