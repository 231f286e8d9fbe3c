#pragma once
// Collects what the Khronos validation layer reports. The project's rule is that the layer must
// report nothing, so the log keeps every warning and error for the caller to assert on.

#include <vulkan/vulkan.h>

#include <cstddef>
#include <mutex>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tilelight {

// Thread-safe: the layer may call back from any thread that makes Vulkan calls.
class ValidationLog {
 public:
  // Number of warnings + errors received since construction or the last clear(), not counting
  // ignored ones.
  std::size_t count() const;
  bool empty() const { return count() == 0; }

  // Copies of the messages, each "[error|warning] <VUID or id name>: <text>".
  std::vector<std::string> messages() const;

  // All messages joined by newlines, for test failure output.
  std::string summary() const;

  // Throws tilelight::Error "<stage>: the validation layer reported N message(s): ..." unless
  // the log is empty.
  void require_empty(std::string_view stage) const;

  void clear();

  // Drops future messages whose id name (the VUID) equals `message_id`. Only for a confirmed
  // layer bug: `reason` must cite the layer's issue. Ignored messages are still counted in
  // ignored_count() so that a filter that hides too much is visible.
  void ignore(std::string message_id, std::string reason);
  std::size_t ignored_count() const;

  // Called by the debug messenger; public so the C callback can reach it.
  void add(VkDebugUtilsMessageSeverityFlagBitsEXT severity, const VkDebugUtilsMessengerCallbackDataEXT& data);

 private:
  mutable std::mutex mutex_;
  std::vector<std::string> messages_;
  std::vector<std::pair<std::string, std::string>> ignored_ids_;  // (VUID, reason)
  std::size_t ignored_count_ = 0;
};

// Fills a messenger create-info that reports warnings and errors of every message type into
// `log`. `log` must outlive the messenger (and the instance, when chained into its pNext).
VkDebugUtilsMessengerCreateInfoEXT make_messenger_info(ValidationLog& log);

}  // namespace tilelight
