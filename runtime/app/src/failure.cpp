#include "tilelight/app/failure.h"

#include "tilelight/vulkan/error.h"

#include <fmt/format.h>

#include <new>

namespace tilelight::app {
namespace {

std::string_view hint(VkResult result) {
  switch (result) {
    case VK_ERROR_OUT_OF_DEVICE_MEMORY:
    case VK_ERROR_OUT_OF_HOST_MEMORY: return " (out of memory: try a smaller --width/--height or fewer --msaa samples)";
    case VK_ERROR_DEVICE_LOST: return " (the device was lost: a driver fault or a GPU reset; no output was written)";
    default: return "";
  }
}

}  // namespace

std::string failure_message(std::string_view stage, const std::exception_ptr& error) {
  try {
    std::rethrow_exception(error);
  } catch (const VulkanError& e) {
    return fmt::format("{}: {}{}", stage, e.what(), hint(e.result()));
  } catch (const OptionError& e) {
    // A message about a flag ("--width 0: ...") says all a user needs; any other gets the stage.
    return e.what();
  } catch (const Error& e) {
    return fmt::format("{}: {}", stage, e.what());
  } catch (const std::bad_alloc&) {
    return fmt::format("{}: out of host memory (std::bad_alloc); try a smaller --width/--height", stage);
  } catch (const std::exception& e) {
    return fmt::format("{}: {}", stage, e.what());
  } catch (...) {
    return fmt::format("{}: an unknown exception", stage);
  }
}

}  // namespace tilelight::app
