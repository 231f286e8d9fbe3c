#include "base/file_io.h"

#include <atomic_file/atomic_file.h>
#include <whole_file/whole_file.h>

#include <cstdio>
#include <cstring>

namespace shadergen {

// whole_file sizes the string from fstat and reads into it directly: a warm build reads
// megabytes of cache entries, and a stream read would copy every byte twice.
Result<std::string> read_file(const std::filesystem::path& path) {
  std::string bytes;
  if (std::optional<whole_file::Failure> failure = whole_file::read(path, bytes)) {
    const char* what = failure->step == whole_file::Failure::Step::open ? "cannot read: " : "read failed: ";
    return make_error(path.string(), 0, what + failure->reason.message());
  }
  return bytes;
}

Status write_file_atomic(const std::filesystem::path& path, std::string_view bytes, bool durable) {
  std::optional<atomic_file::Failure> failure = atomic_file::write(path, bytes, durable);
  if (!failure) return Ok{};
  // Named after the output the user asked for, never the temporary that no longer exists.
  const char* what = failure->step == atomic_file::Failure::Step::create  ? "cannot write: "
                     : failure->step == atomic_file::Failure::Step::write ? "write failed: "
                                                                          : "cannot replace: ";
  return make_error(path.string(), 0, what + failure->reason.message());
}

// Compares in blocks, so checking megabytes of unchanged output allocates nothing.
bool file_has_bytes(const std::filesystem::path& path, std::string_view bytes) {
  std::error_code ec;
  auto size = std::filesystem::file_size(path, ec);
  if (ec || size != bytes.size()) return false;
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) return false;
  char block[1 << 16];
  std::size_t offset = 0;
  bool same = true;
  while (same) {
    std::size_t got = std::fread(block, 1, sizeof block, file);
    if (got == 0) break;
    same = offset + got <= bytes.size() && std::memcmp(block, bytes.data() + offset, got) == 0;
    offset += got;
  }
  same = same && !std::ferror(file) && offset == bytes.size();
  std::fclose(file);
  return same;
}

bool files_equal(const std::filesystem::path& a, const std::filesystem::path& b) {
  std::error_code ec;
  auto size = std::filesystem::file_size(a, ec);
  if (ec || size != std::filesystem::file_size(b, ec) || ec) return false;
  std::FILE* first = std::fopen(a.c_str(), "rb");
  if (!first) return false;
  std::FILE* second = std::fopen(b.c_str(), "rb");
  if (!second) {
    std::fclose(first);
    return false;
  }
  static constexpr std::size_t kBlock = 1 << 16;
  std::string blocks(2 * kBlock, '\0');
  std::size_t offset = 0;
  bool same = true;
  while (same) {
    std::size_t got = std::fread(blocks.data(), 1, kBlock, first);
    std::size_t other = std::fread(blocks.data() + kBlock, 1, kBlock, second);
    same = got == other && std::memcmp(blocks.data(), blocks.data() + kBlock, got) == 0;
    offset += got;
    if (got == 0) break;
  }
  same = same && !std::ferror(first) && !std::ferror(second) && offset == size;
  std::fclose(first);
  std::fclose(second);
  return same;
}

}  // namespace shadergen
