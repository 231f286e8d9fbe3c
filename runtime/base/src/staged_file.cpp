#include "tilelight/base/staged_file.h"

#include "tilelight/base/error.h"

#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <system_error>
#include <utility>

namespace tilelight {
namespace fs = std::filesystem;
namespace {

fs::path temporary_beside(const fs::path& final_path) {
  return final_path.parent_path() /
         fmt::format(".{}.tmp-{}", final_path.filename().string(), static_cast<long>(::getpid()));
}

// Writes `bytes` to `path` and closes it, reporting the OS reason on failure.
void write_whole_file(const fs::path& path, std::span<const std::uint8_t> bytes) {
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (file == nullptr) {
    throw Error(fmt::format("cannot create {}: {}", path.string(), std::strerror(errno)));
  }
  // fwrite's buffer must not be null, even for 0 bytes (an empty span's data() may be).
  const std::size_t written = bytes.empty() ? 0 : std::fwrite(bytes.data(), 1, bytes.size(), file);
  const int write_errno = errno;
  // fclose flushes; a full disk may only show up here.
  const bool closed = std::fclose(file) == 0;
  if (written != bytes.size() || !closed) {
    const int reason = written != bytes.size() ? write_errno : errno;
    throw Error(fmt::format("cannot write {}: {}", path.string(), std::strerror(reason)));
  }
}

void remove_quietly(const fs::path& path) {
  std::error_code ignored;
  fs::remove(path, ignored);
}

}  // namespace

StagedFile::StagedFile(fs::path final_path, std::span<const std::uint8_t> bytes)
    : final_(std::move(final_path)), temporary_(temporary_beside(final_)) {
  try {
    write_whole_file(temporary_, bytes);
  } catch (...) {
    remove_quietly(temporary_);
    throw;
  }
}

StagedFile::~StagedFile() {
  if (!temporary_.empty()) remove_quietly(temporary_);
}

StagedFile::StagedFile(StagedFile&& other) noexcept
    : final_(std::move(other.final_)), temporary_(std::exchange(other.temporary_, {})) {}

void StagedFile::commit() {
  std::error_code ec;
  fs::rename(temporary_, final_, ec);
  if (ec) {
    remove_quietly(temporary_);
    const fs::path temporary = std::exchange(temporary_, {});
    throw Error(fmt::format("renaming {} to {} failed: {}", temporary.string(), final_.string(), ec.message()));
  }
  temporary_.clear();
}

void write_file_atomically(const fs::path& path, std::span<const std::uint8_t> bytes) {
  StagedFile(path, bytes).commit();
}

}  // namespace tilelight
