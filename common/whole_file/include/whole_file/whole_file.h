// whole_file.h - the project's one way to read a whole file into memory: the glTF loader's
// files, buffers and images, the benchmarks' logs and documents, shadergen's inputs.
//
// No exceptions and no message wording, like atomic_file.h: a failure comes back as a Failure
// (which step, which file, the OS reason) and each caller words it in its own error model
// (shadergen's Result, tilelight's Error, a tinygltf callback's error string). describe() gives
// a default wording that names the path and the reason.
#pragma once

#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

namespace whole_file {

struct Failure {
  enum class Step {
    open,       // the file could not be opened (missing, no permission, ...)
    read,       // reading it failed; a folder fails here with std::errc::is_a_directory
    too_large,  // it holds more than the caller's max_bytes (`reason` is std::errc::file_too_large)
  };
  Step step;
  std::filesystem::path path;
  std::error_code reason;
  std::uint64_t size = 0;   // too_large: the file's size (what had arrived, for a pipe)
  std::uint64_t limit = 0;  // too_large: the caller's max_bytes
};

// "<path>: cannot open: <reason>", "<path>: read failed: <reason>" or "<path>: <size> bytes,
// more than the <limit> allowed".
std::string describe(const Failure& failure);

inline constexpr std::uint64_t kNoLimit = std::numeric_limits<std::uint64_t>::max();

// Reads all of `path` into `bytes` (replacing what it held). Works on anything read() reads to
// its end (regular files, pipes, /proc files), retrying interrupted reads. A file of more than
// `max_bytes` bytes is refused before any of it is read when its size is known, else as soon as
// more arrived. Returns the failure, or nothing when `bytes` holds the whole file; after a
// failure `bytes` is empty.
std::optional<Failure> read(const std::filesystem::path& path, std::string& bytes, std::uint64_t max_bytes = kNoLimit);
std::optional<Failure> read(const std::filesystem::path& path, std::vector<std::uint8_t>& bytes,
                            std::uint64_t max_bytes = kNoLimit);

}  // namespace whole_file
