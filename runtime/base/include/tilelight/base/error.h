#pragma once
// The one exception type of the runtime: every library below throws tilelight::Error (or a
// type derived from it, such as the Vulkan layer's VulkanError), so the demo reports any
// failure the same way: the stage it was in, then what() of the error.

#include <stdexcept>
#include <string>
#include <utility>

namespace tilelight {

// Base of every error the runtime throws (configuration, I/O, Vulkan, timeouts). what() names
// the value or file at fault.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// An error about the value of one option. option() names it as the thrower knows it: a
// RendererOptions member ("width") in the libraries, a command-line flag ("--width") in the
// tools, which rethrow the first as the second; what() starts with the option and its value
// ("width 0: ..."), so it needs no further context.
class OptionError : public Error {
 public:
  OptionError(std::string option, const std::string& what) : Error(what), option_(std::move(option)) {}
  const std::string& option() const noexcept { return option_; }

 private:
  std::string option_;
};

}  // namespace tilelight
