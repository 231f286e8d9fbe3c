#pragma once
// Which physical device the runtime uses. The choice is a pure function over a list of
// candidates so that its rules (and its error text) can be tested without a GPU.

#include <vulkan/vulkan.h>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace tilelight {

// What the runtime knows about one enumerated physical device.
struct DeviceInfo {
  std::uint32_t index = 0;  // position in vkEnumeratePhysicalDevices order
  std::string name;         // VkPhysicalDeviceProperties::deviceName
  VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
  std::uint32_t api_version = 0;
  // Empty when the runtime can use the device; otherwise why not ("Vulkan 1.1 < 1.2", "no queue
  // family with graphics and compute", "no timeline semaphores").
  std::string unusable_reason;

  bool usable() const { return unusable_reason.empty(); }
};

// How the caller asks for a device. All empty: the default (see select_device).
struct DeviceRequest {
  std::string name;                    // case-insensitive substring of the device name
  std::optional<std::uint32_t> index;  // enumeration index
  bool automatic = false;              // the fastest kind present (see select_device)

  // "" -> default, "auto" -> automatic, all digits -> index, anything else -> name substring.
  // For --device options.
  static DeviceRequest parse(std::string_view text);
  bool is_default() const { return name.empty() && !index && !automatic; }
};

// Returns the position in `devices` of the device to use:
// - by index: that device;
// - by name: the first usable device whose name contains `request.name` (case-insensitive);
// - default: the first usable device named "llvmpipe" (lavapipe, the CPU driver the tests and
//   the reference images use), else the first usable CPU-type device, else the first usable one;
// - automatic: the first usable discrete GPU, else the first usable integrated GPU, else as the
//   default (tilelight's --device auto: a real GPU where the machine has one).
// Throws tilelight::Error listing every device (and why unusable ones are) when nothing
// matches, the match is unusable, or the list is empty.
std::size_t select_device(std::span<const DeviceInfo> devices, const DeviceRequest& request);

// The same with a request in its command-line form (see DeviceRequest::parse).
const DeviceInfo& select_device(const std::vector<DeviceInfo>& devices, std::string_view request);

// One line per device: "  [0] llvmpipe (LLVM 15.0.6, 256 bits) (cpu, Vulkan 1.3.230)".
std::string describe_devices(std::span<const DeviceInfo> devices);

// "cpu", "discrete GPU", ...
std::string_view device_type_name(VkPhysicalDeviceType type);

// "1.3.230"
std::string api_version_text(std::uint32_t version);

// An enumerated physical device with the queue family the runtime would use on it.
struct PhysicalDevice {
  VkPhysicalDevice handle = VK_NULL_HANDLE;
  DeviceInfo info;
  std::uint32_t queue_family = 0;  // valid only when info.usable()
};

// Enumerates the instance's physical devices and checks each against the runtime's needs
// (Vulkan 1.2, one queue family with graphics + compute, timeline semaphores).
std::vector<PhysicalDevice> enumerate_devices(VkInstance instance);

// enumerate_devices() without the handles, e.g. for --list-devices.
std::vector<DeviceInfo> list_devices(VkInstance instance);

}  // namespace tilelight
