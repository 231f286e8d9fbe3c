#pragma once
// The headless Vulkan context: instance (optionally with the Khronos validation layer), one
// physical device chosen by name, index or default, and one device with a graphics+compute
// queue. Vulkan 1.2 with timeline semaphores, which the deferred draw patching relies on.

#include "tilelight/validation.h"
#include "tilelight/vk_handles.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace tilelight {

struct DeviceInfo {
  std::uint32_t index = 0;  // position in vkEnumeratePhysicalDevices order
  std::string name;
  VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
  std::uint32_t api_version = 0;
};

// Picks a device. `request` empty: the CPU device (lavapipe) if there is one, else the first.
// A request made only of digits is an index; anything else is a case-insensitive substring of
// the name. Throws Error naming the request and listing the devices when nothing matches.
// Precondition: `devices` is not empty.
const DeviceInfo& select_device(const std::vector<DeviceInfo>& devices, std::string_view request);

// MSAA sample count for the G-buffer. `requested` 0 means "2x where the device offers it for
// colour, depth and sampled images, else 4x" (lavapipe offers only 1x and 4x). An explicit
// count the device lacks throws Error naming the value and the supported counts.
VkSampleCountFlagBits choose_msaa(VkSampleCountFlags supported, std::uint32_t requested);

struct ContextOptions {
  std::string device;       // see select_device
  bool validation = false;  // VK_LAYER_KHRONOS_validation + a messenger counting messages
};

class Context {
 public:
  explicit Context(const ContextOptions& options);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  VkInstance instance() const { return instance_.get(); }
  VkPhysicalDevice physical_device() const { return physical_device_; }
  VkDevice device() const { return device_.get(); }
  VkQueue queue() const { return queue_; }
  std::uint32_t queue_family() const { return queue_family_; }
  const DeviceInfo& device_info() const { return info_; }
  const VkPhysicalDeviceProperties& properties() const { return properties_; }

  // Sample counts usable for colour and depth attachments and sampled images alike.
  VkSampleCountFlags msaa_counts() const;

  // The validation log, or nullptr when validation is off.
  const ValidationLog* validation() const { return log_.get(); }
  ValidationLog* validation() { return log_.get(); }

 private:
  // Declared in destruction order's reverse: the device goes before the messenger and the
  // instance; the log outlives them all because the layer may report during their destruction.
  std::unique_ptr<ValidationLog> log_;
  UniqueInstance instance_;
  UniqueDebugMessenger messenger_;
  VkPhysicalDevice physical_device_ = VK_NULL_HANDLE;
  DeviceInfo info_;
  VkPhysicalDeviceProperties properties_{};
  std::uint32_t queue_family_ = 0;
  UniqueDevice device_;
  VkQueue queue_ = VK_NULL_HANDLE;
};

// Every physical device the instance sees.
std::vector<DeviceInfo> list_devices(VkInstance instance);

}  // namespace tilelight
