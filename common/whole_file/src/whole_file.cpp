#include "whole_file/whole_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>

namespace whole_file {
namespace {

constexpr std::size_t kFirstChunk = 4096;

std::error_code os_error(int error) { return {error, std::generic_category()}; }

// Closes the descriptor on every way out of read_into().
class Descriptor {
 public:
  explicit Descriptor(int fd) : fd_(fd) {}
  ~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

Failure too_large(const std::filesystem::path& path, std::uint64_t size, std::uint64_t limit) {
  return {Failure::Step::too_large, path, std::make_error_code(std::errc::file_too_large), size, limit};
}

// One implementation for both containers: std::string for text (shadergen), bytes for the rest.
template <typename Bytes>
std::optional<Failure> read_into(const std::filesystem::path& path, Bytes& bytes, std::uint64_t max_bytes) {
  bytes.clear();
  Descriptor fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
  if (fd.get() < 0) return Failure{Failure::Step::open, path, os_error(errno)};
  // A folder opens, but is no file to read: say so before read() would.
  struct stat info {};
  const bool have_info = ::fstat(fd.get(), &info) == 0;
  if (have_info && S_ISDIR(info.st_mode))
    return Failure{Failure::Step::read, path, std::make_error_code(std::errc::is_a_directory)};
  const bool known_size = have_info && S_ISREG(info.st_mode);
  if (known_size && static_cast<std::uint64_t>(info.st_size) > max_bytes)
    return too_large(path, static_cast<std::uint64_t>(info.st_size), max_bytes);
  // A regular file's size is only a first guess (it may change while it is read); other files
  // (pipes, /proc) have none.
  const std::size_t expected = known_size ? static_cast<std::size_t>(info.st_size) : SIZE_MAX;
  bytes.resize(known_size ? expected : 0);
  std::size_t used = 0;
  for (;;) {
    if (used == bytes.size()) {
      // At a file's expected end a little room is enough to see the end (or that it grew), so
      // a large file is not held twice; a stream doubles, for linear cost overall.
      bytes.resize(used + (used == expected ? kFirstChunk : std::max(used, kFirstChunk)));
    }
    const ssize_t got = ::read(fd.get(), bytes.data() + used, bytes.size() - used);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) {
      const int error = errno;
      bytes.clear();
      return Failure{Failure::Step::read, path, os_error(error)};
    }
    if (got == 0) break;
    used += static_cast<std::size_t>(got);
    if (used > max_bytes) {
      bytes.clear();
      return too_large(path, used, max_bytes);
    }
  }
  bytes.resize(used);
  return std::nullopt;
}

}  // namespace

std::string describe(const Failure& failure) {
  const std::string path = failure.path.string();
  switch (failure.step) {
    case Failure::Step::open: return path + ": cannot open: " + failure.reason.message();
    case Failure::Step::read: return path + ": read failed: " + failure.reason.message();
    case Failure::Step::too_large:
      return path + ": " + std::to_string(failure.size) + " bytes, more than the " + std::to_string(failure.limit) +
             " allowed";
  }
  return path + ": " + failure.reason.message();
}

std::optional<Failure> read(const std::filesystem::path& path, std::string& bytes, std::uint64_t max_bytes) {
  return read_into(path, bytes, max_bytes);
}

std::optional<Failure> read(const std::filesystem::path& path, std::vector<std::uint8_t>& bytes,
                            std::uint64_t max_bytes) {
  return read_into(path, bytes, max_bytes);
}

}  // namespace whole_file
