#include "file_io.h"

#include <algorithm>
#include <atomic>
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

std::string temporary_name(std::string_view stem) {
  static std::atomic<unsigned> counter{0};
  return "." + std::string(stem) + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
}

Status write_file_atomic(const std::filesystem::path& path, std::string_view bytes) {
  std::filesystem::path temp = path.parent_path() / temporary_name(path.filename().string());
  std::FILE* file = std::fopen(temp.c_str(), "wb");
  if (!file) return make_error(path.string(), 0, std::string("cannot write: ") + std::strerror(errno));
  bool ok = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
  int write_errno = errno;
  ok = (std::fflush(file) == 0) && ok;
  if (!ok) write_errno = errno;
  ok = (::fsync(::fileno(file)) == 0 || errno == EINVAL) && ok;
  ok = (std::fclose(file) == 0) && ok;
  if (!ok) {
    std::remove(temp.c_str());
    return make_error(path.string(), 0, std::string("write failed: ") + std::strerror(write_errno ? write_errno : EIO));
  }
  if (std::rename(temp.c_str(), path.c_str()) != 0) {
    int rename_errno = errno;
    std::remove(temp.c_str());
    return make_error(path.string(), 0, std::string("cannot replace: ") + std::strerror(rename_errno));
  }
  return Ok{};
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
