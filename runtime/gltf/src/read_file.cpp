#include "read_file.h"

#include "tilelight/base/error.h"

#include <fmt/format.h>

#include <system_error>

namespace tilelight::gltf_detail {

std::string describe_read_failure(const whole_file::Failure& failure, const std::string& what) {
  using Step = whole_file::Failure::Step;
  if (failure.step == Step::too_large)
    return fmt::format("{}: {} bytes, more than this loader reads ({})", what, failure.size, kMaxFileBytes);
  if (failure.reason == std::errc::is_a_directory) return what + ": is a folder, not a file";
  return what + (failure.step == Step::open ? ": cannot open: " : ": read failed: ") + failure.reason.message();
}

std::vector<std::uint8_t> read_file(const std::filesystem::path& path, const std::string& what) {
  std::vector<std::uint8_t> bytes;
  if (auto failure = whole_file::read(path, bytes, kMaxFileBytes)) throw Error(describe_read_failure(*failure, what));
  return bytes;
}

}  // namespace tilelight::gltf_detail
