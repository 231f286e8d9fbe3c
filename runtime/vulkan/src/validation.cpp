#include "tilelight/vulkan/validation.h"

#include "tilelight/vulkan/error.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace tilelight {
namespace {

VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                          VkDebugUtilsMessageTypeFlagsEXT /*types*/,
                                          const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  if (data != nullptr && user != nullptr) {
    static_cast<ValidationLog*>(user)->add(severity, *data);
  }
  // VK_FALSE: never abort the call; the message is recorded and the test decides.
  return VK_FALSE;
}

const char* severity_name(VkDebugUtilsMessageSeverityFlagBitsEXT severity) {
  return (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) != 0 ? "error" : "warning";
}

}  // namespace

std::size_t ValidationLog::count() const {
  std::lock_guard lock(mutex_);
  return messages_.size();
}

std::vector<std::string> ValidationLog::messages() const {
  std::lock_guard lock(mutex_);
  return messages_;
}

std::string ValidationLog::summary() const {
  std::lock_guard lock(mutex_);
  return fmt::format("{}", fmt::join(messages_, "\n"));
}

void ValidationLog::require_empty(std::string_view stage) const {
  const std::size_t n = count();
  if (n != 0) {
    throw Error(fmt::format("{}: the validation layer reported {} message(s):\n{}", stage, n, summary()));
  }
}

void ValidationLog::clear() {
  std::lock_guard lock(mutex_);
  messages_.clear();
  ignored_count_ = 0;
}

void ValidationLog::ignore(std::string message_id, std::string reason) {
  std::lock_guard lock(mutex_);
  ignored_ids_.emplace_back(std::move(message_id), std::move(reason));
}

std::size_t ValidationLog::ignored_count() const {
  std::lock_guard lock(mutex_);
  return ignored_count_;
}

void ValidationLog::add(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                        const VkDebugUtilsMessengerCallbackDataEXT& data) {
  const char* id = data.pMessageIdName != nullptr ? data.pMessageIdName : "(no id)";
  const char* text = data.pMessage != nullptr ? data.pMessage : "";
  std::string line = fmt::format("[{}] {}: {}", severity_name(severity), id, text);
  std::lock_guard lock(mutex_);
  for (const auto& [ignored_id, reason] : ignored_ids_) {
    if (ignored_id == id) {
      ++ignored_count_;
      return;
    }
  }
  messages_.push_back(std::move(line));
}

VkDebugUtilsMessengerCreateInfoEXT make_messenger_info(ValidationLog& log) {
  VkDebugUtilsMessengerCreateInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  info.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  info.pfnUserCallback = &on_message;
  info.pUserData = &log;
  return info;
}

}  // namespace tilelight
