#include "atomic_file/atomic_file.h"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <utility>

namespace atomic_file {
namespace fs = std::filesystem;
namespace {

// errno after a failed call; EIO when the call failed without setting it (a short fwrite may).
int last_error() { return errno != 0 ? errno : EIO; }

// Writes, flushes and (when `durable`) syncs `bytes` into a new file at `path`, and closes it.
std::optional<Failure> write_whole_file(const fs::path& path, std::string_view bytes, bool durable) {
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (file == nullptr)
    return Failure{Failure::Step::create, path, std::error_code(last_error(), std::generic_category())};
  // Each step runs only while the ones before it succeeded; `reason` is the first failure's.
  int reason = 0;
  // fwrite's buffer must not be null, even for 0 bytes (an empty view's data() may be).
  if (!bytes.empty() && std::fwrite(bytes.data(), 1, bytes.size(), file) != bytes.size()) reason = last_error();
  // A full disk may only show up at the flush; fsync makes the rename publish written bytes
  // (EINVAL: a file system that cannot sync, such as some FUSE mounts, is not an error).
  if (reason == 0 && std::fflush(file) != 0) reason = last_error();
  if (reason == 0 && durable && ::fsync(::fileno(file)) != 0 && errno != EINVAL) reason = last_error();
  if (std::fclose(file) != 0 && reason == 0) reason = last_error();
  if (reason != 0) return Failure{Failure::Step::write, path, std::error_code(reason, std::generic_category())};
  return std::nullopt;
}

void remove_quietly(const fs::path& path) {
  std::error_code ignored;
  fs::remove(path, ignored);
}

}  // namespace

std::string describe(const Failure& failure) {
  const char* verb = failure.step == Failure::Step::create  ? "cannot create "
                     : failure.step == Failure::Step::write ? "cannot write "
                                                            : "cannot replace ";
  return verb + failure.path.string() + ": " + failure.reason.message();
}

std::string temporary_name(std::string_view stem) {
  static std::atomic<unsigned> counter{0};
  std::string name(".");
  name.append(stem).append(".tmp-").append(std::to_string(::getpid())).append("-").append(std::to_string(counter++));
  return name;
}

StagedFile::StagedFile(fs::path final_path, std::string_view bytes, bool durable)
    : final_(std::move(final_path)), temporary_(final_.parent_path() / temporary_name(final_.filename().string())) {
  failure_ = write_whole_file(temporary_, bytes, durable);
  if (failure_) {
    remove_quietly(temporary_);
    temporary_.clear();
  }
}

StagedFile::~StagedFile() {
  if (!temporary_.empty()) remove_quietly(temporary_);
}

StagedFile::StagedFile(StagedFile&& other) noexcept
    : final_(std::move(other.final_)),
      temporary_(std::exchange(other.temporary_, {})),
      failure_(std::move(other.failure_)) {}

std::optional<Failure> StagedFile::commit() {
  std::error_code ec;
  fs::rename(temporary_, final_, ec);
  if (ec) {
    remove_quietly(std::exchange(temporary_, {}));
    return Failure{Failure::Step::replace, final_, ec};
  }
  temporary_.clear();
  return std::nullopt;
}

std::optional<Failure> write(const fs::path& path, std::string_view bytes, bool durable) {
  StagedFile staged(path, bytes, durable);
  if (staged.failure()) return staged.failure();
  return staged.commit();
}

}  // namespace atomic_file
