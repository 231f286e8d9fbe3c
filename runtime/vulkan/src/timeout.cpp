#include "tilelight/vulkan/timeout.h"

#include "tilelight/vulkan/error.h"

#include <fmt/format.h>

#include <limits>

namespace tilelight {

std::uint64_t timeout_ns(Seconds timeout) {
  const double ns = timeout.count() * 1e9;
  if (!(ns > 0.0)) {  // also catches NaN
    return 0;
  }
  // 2^64 as a double; anything at or above it saturates (UINT64_MAX means "forever" to Vulkan,
  // which a finite request never should, so stop one short of it).
  constexpr double kLimit = 18446744073709551616.0;
  if (ns >= kLimit) {
    return std::numeric_limits<std::uint64_t>::max() - 1;
  }
  return static_cast<std::uint64_t>(ns);
}

std::string timeout_message(std::string_view stage, Seconds timeout) {
  return fmt::format("GPU did not finish {} within {:g} s", stage, timeout.count());
}

void throw_timeout(std::string_view stage, Seconds timeout) { throw TimeoutError(timeout_message(stage, timeout)); }

}  // namespace tilelight
