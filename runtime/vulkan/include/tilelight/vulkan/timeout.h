#pragma once
// Every wait on the GPU is bounded. A hang (a missed host signal, a deadlocked queue, a driver
// bug) must end the run with a message that names the stage, never block CI forever.

#include <chrono>
#include <cstdint>
#include <string>
#include <string_view>

namespace tilelight {

using Seconds = std::chrono::duration<double>;

// Generous for lavapipe at 1280x720 with MSAA on a 2-core CI machine.
inline constexpr Seconds kDefaultGpuTimeout{60.0};

// The timeout in nanoseconds for vkWaitForFences / vkWaitSemaphores; negative -> 0, and values
// beyond the uint64 range saturate.
std::uint64_t timeout_ns(Seconds timeout);

// "GPU did not finish <stage> within <N> s"
std::string timeout_message(std::string_view stage, Seconds timeout);

// Throws TimeoutError(timeout_message(stage, timeout)).
[[noreturn]] void throw_timeout(std::string_view stage, Seconds timeout);

}  // namespace tilelight
