#include "tilelight/vulkan/device_selection.h"

#include "tilelight/vulkan/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

namespace tilelight {
namespace {

std::string lower(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

bool contains_ci(std::string_view haystack, std::string_view needle) {
  return lower(haystack).find(lower(needle)) != std::string::npos;
}

[[noreturn]] void fail(std::string_view what, std::span<const DeviceInfo> candidates) {
  throw Error(fmt::format("{}; available Vulkan devices:\n{}", what, describe_devices(candidates)));
}

// First usable candidate satisfying `pred`, if any.
template <typename Pred>
std::optional<std::size_t> first_usable(std::span<const DeviceInfo> candidates, Pred pred) {
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (candidates[i].usable() && pred(candidates[i])) {
      return i;
    }
  }
  return std::nullopt;
}

std::optional<std::uint32_t> graphics_compute_family(VkPhysicalDevice device) {
  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
  constexpr VkQueueFlags kNeeded = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
  for (std::uint32_t i = 0; i < count; ++i) {
    if ((families[i].queueFlags & kNeeded) == kNeeded && families[i].queueCount > 0) {
      return i;
    }
  }
  return std::nullopt;
}

bool has_timeline_semaphores(VkPhysicalDevice device) {
  VkPhysicalDeviceVulkan12Features features12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  features.pNext = &features12;
  vkGetPhysicalDeviceFeatures2(device, &features);
  return features12.timelineSemaphore == VK_TRUE;
}

}  // namespace

DeviceRequest DeviceRequest::parse(std::string_view text) {
  DeviceRequest request;
  if (text.empty()) {
    return request;
  }
  if (text == "auto") {
    request.automatic = true;
    return request;
  }
  const bool digits = text.size() <= 9 && std::all_of(text.begin(), text.end(), [](char c) {
                        return std::isdigit(static_cast<unsigned char>(c)) != 0;
                      });
  if (digits) {
    request.index = static_cast<std::uint32_t>(std::stoul(std::string(text)));
  } else {
    request.name = std::string(text);
  }
  return request;
}

std::size_t select_device(std::span<const DeviceInfo> candidates, const DeviceRequest& request) {
  if (candidates.empty()) {
    throw Error(
        "no Vulkan devices found (is a Vulkan driver installed? mesa-vulkan-drivers provides "
        "lavapipe, the CPU driver)");
  }
  if (request.index && !request.name.empty()) {
    throw Error(fmt::format("ask for a Vulkan device by index ({}) or by name (\"{}\"), not both", *request.index,
                            request.name));
  }

  if (request.index) {
    const std::uint32_t wanted = *request.index;
    const auto it =
        std::find_if(candidates.begin(), candidates.end(), [&](const DeviceInfo& c) { return c.index == wanted; });
    if (it == candidates.end()) {
      fail(fmt::format("Vulkan device index {} does not exist", wanted), candidates);
    }
    if (!it->usable()) {
      fail(fmt::format("Vulkan device {} ({}) cannot be used: {}", wanted, it->name, it->unusable_reason), candidates);
    }
    return static_cast<std::size_t>(it - candidates.begin());
  }

  if (!request.name.empty()) {
    if (auto found = first_usable(candidates, [&](const DeviceInfo& c) { return contains_ci(c.name, request.name); })) {
      return *found;
    }
    const bool unusable_match = std::any_of(candidates.begin(), candidates.end(),
                                            [&](const DeviceInfo& c) { return contains_ci(c.name, request.name); });
    fail(fmt::format("no {}Vulkan device matches \"{}\"", unusable_match ? "usable " : "", request.name), candidates);
  }

  if (request.automatic) {
    for (const VkPhysicalDeviceType type :
         {VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU}) {
      if (auto found = first_usable(candidates, [type](const DeviceInfo& c) { return c.type == type; })) return *found;
    }
  }
  if (auto found = first_usable(candidates, [](const DeviceInfo& c) { return contains_ci(c.name, "llvmpipe"); })) {
    return *found;
  }
  if (auto found =
          first_usable(candidates, [](const DeviceInfo& c) { return c.type == VK_PHYSICAL_DEVICE_TYPE_CPU; })) {
    return *found;
  }
  if (auto found = first_usable(candidates, [](const DeviceInfo&) { return true; })) {
    return *found;
  }
  fail("no Vulkan device is usable", candidates);
}

const DeviceInfo& select_device(const std::vector<DeviceInfo>& devices, std::string_view request) {
  return devices[select_device(std::span<const DeviceInfo>(devices), DeviceRequest::parse(request))];
}

std::string describe_devices(std::span<const DeviceInfo> candidates) {
  std::string out;
  for (const DeviceInfo& c : candidates) {
    out += fmt::format("  [{}] {} ({}, Vulkan {})", c.index, c.name, device_type_name(c.type),
                       api_version_text(c.api_version));
    if (!c.usable()) {
      out += fmt::format(" - unusable: {}", c.unusable_reason);
    }
    out += '\n';
  }
  if (candidates.empty()) {
    out = "  (none)\n";
  }
  return out;
}

std::string_view device_type_name(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated GPU";
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete GPU";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual GPU";
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return "cpu";
    default: return "other";
  }
}

std::string api_version_text(std::uint32_t version) {
  return fmt::format("{}.{}.{}", VK_API_VERSION_MAJOR(version), VK_API_VERSION_MINOR(version),
                     VK_API_VERSION_PATCH(version));
}

std::vector<PhysicalDevice> enumerate_devices(VkInstance instance) {
  std::uint32_t count = 0;
  check(vkEnumeratePhysicalDevices(instance, &count, nullptr), "vkEnumeratePhysicalDevices", "the device list");
  std::vector<VkPhysicalDevice> handles(count);
  // VK_INCOMPLETE cannot happen here (same count, nothing changes in between), so check() is
  // strict on purpose.
  check(vkEnumeratePhysicalDevices(instance, &count, handles.data()), "vkEnumeratePhysicalDevices", "the device list");
  handles.resize(count);

  std::vector<PhysicalDevice> devices;
  for (std::uint32_t i = 0; i < count; ++i) {
    VkPhysicalDeviceProperties props{};
    vkGetPhysicalDeviceProperties(handles[i], &props);
    PhysicalDevice device;
    device.handle = handles[i];
    device.info.index = i;
    device.info.name = props.deviceName;
    device.info.type = props.deviceType;
    device.info.api_version = props.apiVersion;
    const auto family = graphics_compute_family(handles[i]);
    if (props.apiVersion < VK_API_VERSION_1_2) {
      // Timeline semaphores and the Vulkan12 feature struct need a 1.2 device.
      device.info.unusable_reason = fmt::format("Vulkan {} < 1.2", api_version_text(props.apiVersion));
    } else if (!family) {
      device.info.unusable_reason = "no queue family with graphics and compute";
    } else if (!has_timeline_semaphores(handles[i])) {
      device.info.unusable_reason = "no timeline semaphores";
    } else {
      device.queue_family = *family;
    }
    devices.push_back(std::move(device));
  }
  return devices;
}

std::vector<DeviceInfo> list_devices(VkInstance instance) {
  std::vector<DeviceInfo> out;
  for (PhysicalDevice& device : enumerate_devices(instance)) {
    out.push_back(std::move(device.info));
  }
  return out;
}

}  // namespace tilelight
