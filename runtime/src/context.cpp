#include "tilelight/context.h"

#include "tilelight/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstring>

namespace tilelight {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

std::string lower(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

std::string describe(const std::vector<DeviceInfo>& devices) {
  std::string text;
  for (const DeviceInfo& d : devices) text += fmt::format("\n  {}: {}", d.index, d.name);
  return text;
}

bool layer_available(const char* name) {
  std::uint32_t count = 0;
  check(vkEnumerateInstanceLayerProperties(&count, nullptr), "vkEnumerateInstanceLayerProperties");
  std::vector<VkLayerProperties> layers(count);
  check(vkEnumerateInstanceLayerProperties(&count, layers.data()), "vkEnumerateInstanceLayerProperties");
  return std::any_of(layers.begin(), layers.end(),
                     [&](const VkLayerProperties& l) { return std::strcmp(l.layerName, name) == 0; });
}

UniqueInstance create_instance(ValidationLog* log) {
  VkApplicationInfo app{};
  app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
  app.pApplicationName = "tilelight";
  app.apiVersion = VK_API_VERSION_1_2;
  VkInstanceCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
  info.pApplicationInfo = &app;
  const char* layers[] = {kValidationLayer};
  const char* extensions[] = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME};
  VkDebugUtilsMessengerCreateInfoEXT messenger{};
  if (log != nullptr) {
    if (!layer_available(kValidationLayer))
      throw Error(fmt::format("--validation: the layer {} is not installed (Debian package: vulkan-validationlayers)",
                              kValidationLayer));
    info.enabledLayerCount = 1;
    info.ppEnabledLayerNames = layers;
    info.enabledExtensionCount = 1;
    info.ppEnabledExtensionNames = extensions;
    // Chained so that instance creation and destruction are validated too.
    messenger = make_messenger_info(*log);
    info.pNext = &messenger;
  }
  VkInstance instance = VK_NULL_HANDLE;
  check(vkCreateInstance(&info, nullptr, &instance), "vkCreateInstance", "creating the Vulkan instance");
  return UniqueInstance(instance, InstanceDeleter{});
}

UniqueDebugMessenger create_messenger(VkInstance instance, ValidationLog& log) {
  auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
  auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
  if (create == nullptr || destroy == nullptr) throw Error("VK_EXT_debug_utils entry points are missing");
  VkDebugUtilsMessengerCreateInfoEXT info = make_messenger_info(log);
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  check(create(instance, &info, nullptr, &messenger), "vkCreateDebugUtilsMessengerEXT", "enabling validation");
  return UniqueDebugMessenger(messenger, DebugMessengerDeleter{instance, destroy});
}

std::uint32_t find_queue_family(VkPhysicalDevice device, const std::string& name) {
  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
  constexpr VkQueueFlags wanted = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
  for (std::uint32_t i = 0; i < count; ++i)
    if ((families[i].queueFlags & wanted) == wanted && families[i].timestampValidBits > 0) return i;
  throw Error(fmt::format("device \"{}\" has no queue with graphics, compute and timestamps", name));
}

}  // namespace

std::vector<DeviceInfo> list_devices(VkInstance instance) {
  std::uint32_t count = 0;
  check(vkEnumeratePhysicalDevices(instance, &count, nullptr), "vkEnumeratePhysicalDevices");
  std::vector<VkPhysicalDevice> handles(count);
  check(vkEnumeratePhysicalDevices(instance, &count, handles.data()), "vkEnumeratePhysicalDevices");
  std::vector<DeviceInfo> devices;
  for (std::uint32_t i = 0; i < count; ++i) {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(handles[i], &p);
    devices.push_back({i, p.deviceName, p.deviceType, p.apiVersion});
  }
  return devices;
}

const DeviceInfo& select_device(const std::vector<DeviceInfo>& devices, std::string_view request) {
  if (request.empty()) {
    for (const DeviceInfo& d : devices)
      if (d.type == VK_PHYSICAL_DEVICE_TYPE_CPU) return d;
    return devices.front();
  }
  bool numeric = std::all_of(request.begin(), request.end(), [](unsigned char c) { return std::isdigit(c); });
  if (numeric) {
    unsigned long index = std::stoul(std::string(request));
    if (index < devices.size()) return devices[index];
    throw Error(fmt::format("--device {}: no device with that index; devices:{}", request, describe(devices)));
  }
  std::string wanted = lower(request);
  for (const DeviceInfo& d : devices)
    if (lower(d.name).find(wanted) != std::string::npos) return d;
  throw Error(fmt::format("--device {}: no device name contains \"{}\"; devices:{}", request, request,
                          describe(devices)));
}

VkSampleCountFlagBits choose_msaa(VkSampleCountFlags supported, std::uint32_t requested) {
  if (requested == 0) {
    if (supported & VK_SAMPLE_COUNT_2_BIT) return VK_SAMPLE_COUNT_2_BIT;
    if (supported & VK_SAMPLE_COUNT_4_BIT) return VK_SAMPLE_COUNT_4_BIT;
    throw Error("the device supports neither 2x nor 4x MSAA for the G-buffer");
  }
  bool power_of_two = requested <= 64 && (requested & (requested - 1)) == 0;
  if (power_of_two && (supported & requested)) return static_cast<VkSampleCountFlagBits>(requested);
  std::string counts;
  for (std::uint32_t n = 1; n <= 64; n *= 2)
    if (supported & n) counts += fmt::format("{}{}", counts.empty() ? "" : ", ", n);
  throw Error(fmt::format("--msaa {}: the device does not support {} samples for the G-buffer (supported: {})",
                          requested, requested, counts));
}

Context::Context(const ContextOptions& options) {
  if (options.validation) log_ = std::make_unique<ValidationLog>();
  instance_ = create_instance(log_.get());
  if (log_) messenger_ = create_messenger(instance_.get(), *log_);
  std::vector<DeviceInfo> devices = list_devices(instance_.get());
  if (devices.empty()) throw Error("no Vulkan device found (is mesa-vulkan-drivers installed for lavapipe?)");
  info_ = select_device(devices, options.device);
  std::uint32_t count = static_cast<std::uint32_t>(devices.size());
  std::vector<VkPhysicalDevice> handles(count);
  check(vkEnumeratePhysicalDevices(instance_.get(), &count, handles.data()), "vkEnumeratePhysicalDevices");
  physical_device_ = handles[info_.index];
  vkGetPhysicalDeviceProperties(physical_device_, &properties_);
  if (properties_.apiVersion < VK_API_VERSION_1_2)
    throw Error(fmt::format("device \"{}\" supports Vulkan {}.{}; tilelight needs 1.2", info_.name,
                            VK_API_VERSION_MAJOR(properties_.apiVersion), VK_API_VERSION_MINOR(properties_.apiVersion)));
  queue_family_ = find_queue_family(physical_device_, info_.name);

  float priority = 1.0f;
  VkDeviceQueueCreateInfo queue{};
  queue.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
  queue.queueFamilyIndex = queue_family_;
  queue.queueCount = 1;
  queue.pQueuePriorities = &priority;
  VkPhysicalDeviceVulkan12Features features12{};
  features12.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES;
  features12.timelineSemaphore = VK_TRUE;
  VkDeviceCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
  info.pNext = &features12;
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue;
  VkDevice device = VK_NULL_HANDLE;
  check(vkCreateDevice(physical_device_, &info, nullptr, &device), "vkCreateDevice",
        fmt::format("creating the device on \"{}\"", info_.name));
  device_ = UniqueDevice(device, DeviceDeleter{});
  vkGetDeviceQueue(device, queue_family_, 0, &queue_);
}

Context::~Context() {
  if (device_) vkDeviceWaitIdle(device_.get());  // nothing may be in flight when handles go
}

VkSampleCountFlags Context::msaa_counts() const {
  const VkPhysicalDeviceLimits& l = properties_.limits;
  return l.framebufferColorSampleCounts & l.framebufferDepthSampleCounts & l.sampledImageColorSampleCounts &
         l.sampledImageDepthSampleCounts;
}

}  // namespace tilelight
