#include "base/file_io.h"

#include <atomic_file/atomic_file.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace shadergen {

// One read() into a string sized from fstat: a warm build reads megabytes of cache entries,
// and a stream read through an intermediate buffer costs a second copy of every byte.
Result<std::string> read_file(const std::filesystem::path& path) {
  int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return make_error(path.string(), 0, std::string("cannot read: ") + std::strerror(errno));
  struct stat info {};
  std::string bytes;
  if (::fstat(fd, &info) == 0 && S_ISREG(info.st_mode)) bytes.resize(static_cast<std::size_t>(info.st_size));
  std::size_t used = 0;
  for (;;) {
    if (used == bytes.size()) bytes.resize(std::max<std::size_t>(bytes.size() * 2, 4096));  // grew, or not a file
    ssize_t got = ::read(fd, bytes.data() + used, bytes.size() - used);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) {
      int error = errno;
      ::close(fd);
      return make_error(path.string(), 0, std::string("read failed: ") + std::strerror(error));
    }
    if (got == 0) break;
    used += static_cast<std::size_t>(got);
  }
  ::close(fd);
  bytes.resize(used);
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

}  // namespace shadergen
