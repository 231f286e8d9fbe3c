#pragma once
// How a failed run is reported: one line that says which stage of the run failed and why, so
// that an out-of-memory error, a lost device or a driver exception never ends the program
// without a message that a user can act on.

#include <exception>
#include <string>
#include <string_view>

namespace tilelight::app {

// The message after "tilelight: error: " for `error` thrown while `stage` ran ("creating the
// renderer", "frame 3 of 500"): the stage in front of the cause, and for the Vulkan failures a
// user can act on (out of memory, device lost) a hint. Messages about a command-line value
// ("--width 0: ...") already say what to fix and are passed through unchanged.
// Precondition: `error` is not null.
std::string failure_message(std::string_view stage, const std::exception_ptr& error);

}  // namespace tilelight::app
