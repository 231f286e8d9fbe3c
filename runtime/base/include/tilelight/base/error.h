#pragma once
// The one exception type of the runtime: every library below throws tilelight::Error (or a
// type derived from it, such as the Vulkan layer's VulkanError), so the demo reports any
// failure the same way: the stage it was in, then what() of the error.

#include <stdexcept>

namespace tilelight {

// Base of every error the runtime throws (configuration, I/O, Vulkan, timeouts). what() names
// the value or file at fault.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace tilelight
