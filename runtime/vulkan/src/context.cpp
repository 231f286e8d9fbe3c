#include "tilelight/vulkan/context.h"

#include "tilelight/vulkan/error.h"
#include "tilelight/vulkan/msaa.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <cstring>

namespace tilelight {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool layer_available(const char* name) {
  std::uint32_t count = 0;
  check(vkEnumerateInstanceLayerProperties(&count, nullptr), "vkEnumerateInstanceLayerProperties", "the layer list");
  std::vector<VkLayerProperties> layers(count);
  check(vkEnumerateInstanceLayerProperties(&count, layers.data()), "vkEnumerateInstanceLayerProperties",
        "the layer list");
  return std::any_of(layers.begin(), layers.begin() + count,
                     [&](const VkLayerProperties& layer) { return std::strcmp(layer.layerName, name) == 0; });
}

// Whether `device` offers the device extension `name`.
bool device_extension_available(VkPhysicalDevice device, const char* name) {
  std::uint32_t count = 0;
  check(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr), "vkEnumerateDeviceExtensionProperties",
        "the device's extensions");
  std::vector<VkExtensionProperties> extensions(count);
  check(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data()),
        "vkEnumerateDeviceExtensionProperties", "the device's extensions");
  return std::any_of(extensions.begin(), extensions.begin() + count,
                     [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

// Instance extensions offered by the loader and drivers (layer == nullptr) or by one layer.
bool instance_extension_available(const char* layer, const char* name) {
  std::uint32_t count = 0;
  check(vkEnumerateInstanceExtensionProperties(layer, &count, nullptr), "vkEnumerateInstanceExtensionProperties",
        "the instance extension list");
  std::vector<VkExtensionProperties> extensions(count);
  check(vkEnumerateInstanceExtensionProperties(layer, &count, extensions.data()),
        "vkEnumerateInstanceExtensionProperties", "the instance extension list");
  return std::any_of(extensions.begin(), extensions.begin() + count,
                     [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

}  // namespace

Context::Context(const ContextOptions& options) : log_(std::make_shared<ValidationLog>()) {
  create_instance(options);
  pick_device(options);
  create_device();
}

Context::~Context() {
  if (!device_) {
    return;
  }
  try {
    wait_idle("the last submitted work before destroying the Vulkan device", Seconds{10.0});
  } catch (const std::exception& e) {
    // Destroying a device whose queue still runs is undefined behaviour and vkDeviceWaitIdle
    // could block forever, so leak instead; the process is about to report a failure anyway.
    std::fprintf(stderr,
                 "tilelight: %s; leaking the Vulkan device and instance instead of destroying "
                 "them while in use\n",
                 e.what());
    (void)device_.release();
    (void)messenger_.release();
    (void)instance_.release();
    // The layer may still call back into the log: keep it alive for good.
    [[maybe_unused]] auto* leaked = new std::shared_ptr<ValidationLog>(log_);
  }
}

namespace {

void require_vulkan_1_2_loader() {
  std::uint32_t loader_version = VK_API_VERSION_1_0;
  check(vkEnumerateInstanceVersion(&loader_version), "vkEnumerateInstanceVersion");
  if (loader_version < VK_API_VERSION_1_2) {
    throw Error(fmt::format("the Vulkan loader supports only Vulkan {}; the runtime needs 1.2",
                            api_version_text(loader_version)));
  }
}

struct InstanceLayers {
  std::vector<const char*> layers;
  std::vector<const char*> extensions;
};

// The validation layer and what it needs, when asked for; an error naming what is missing.
InstanceLayers instance_layers(const ContextOptions& options) {
  InstanceLayers wanted;
  if (!options.validation) return wanted;
  if (!layer_available(kValidationLayer)) {
    throw Error(
        fmt::format("validation was requested but the Khronos validation layer ({}) is not installed "
                    "(Debian: vulkan-validationlayers)",
                    kValidationLayer));
  }
  wanted.layers.push_back(kValidationLayer);
  wanted.extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  if (options.synchronization_validation) {
    if (!instance_extension_available(kValidationLayer, VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME)) {
      throw Error(
          fmt::format("the installed validation layer does not offer {}, needed for synchronization "
                      "validation",
                      VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME));
    }
    wanted.extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
  }
  return wanted;
}

}  // namespace

void Context::create_instance(const ContextOptions& options) {
  if (options.synchronization_validation && !options.validation) {
    throw Error("synchronization validation needs validation enabled as well");
  }
  require_vulkan_1_2_loader();
  const InstanceLayers wanted = instance_layers(options);
  validation_ = options.validation;

  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = options.application_name.c_str();
  app.applicationVersion = 1;
  app.pEngineName = "tilelight";
  app.engineVersion = 1;
  app.apiVersion = VK_API_VERSION_1_2;

  // Chained into the create info, the messenger also sees messages from vkCreateInstance and
  // vkDestroyInstance, which the separate messenger below cannot.
  VkDebugUtilsMessengerCreateInfoEXT messenger_info = make_messenger_info(*log_);
  const VkValidationFeatureEnableEXT sync_validation = VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
  VkValidationFeaturesEXT validation_features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  validation_features.enabledValidationFeatureCount = 1;
  validation_features.pEnabledValidationFeatures = &sync_validation;
  if (options.synchronization_validation) {
    messenger_info.pNext = &validation_features;
  }

  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pNext = validation_ ? &messenger_info : nullptr;
  info.pApplicationInfo = &app;
  info.enabledLayerCount = static_cast<std::uint32_t>(wanted.layers.size());
  info.ppEnabledLayerNames = wanted.layers.data();
  info.enabledExtensionCount = static_cast<std::uint32_t>(wanted.extensions.size());
  info.ppEnabledExtensionNames = wanted.extensions.data();

  VkInstance instance = VK_NULL_HANDLE;
  check(vkCreateInstance(&info, nullptr, &instance), "vkCreateInstance", "the Vulkan instance");
  instance_ = UniqueInstance(instance, InstanceDeleter{});
  if (validation_) create_validation_messenger();
}

void Context::create_validation_messenger() {
  const VkInstance instance = instance_.get();
  // Extension entry points are not exported by the loader; fetch them from the instance.
  auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
  auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
  set_object_name_fn_ = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
      vkGetInstanceProcAddr(instance, "vkSetDebugUtilsObjectNameEXT"));
  if (create == nullptr || destroy == nullptr) {
    throw Error("VK_EXT_debug_utils is enabled but its entry points are missing");
  }
  VkDebugUtilsMessengerCreateInfoEXT standalone = make_messenger_info(*log_);
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  check(create(instance, &standalone, nullptr, &messenger), "vkCreateDebugUtilsMessengerEXT",
        "the validation messenger");
  messenger_ = UniqueDebugMessenger(messenger, DebugMessengerDeleter{instance, destroy});
}

void Context::pick_device(const ContextOptions& options) {
  std::vector<PhysicalDevice> devices = enumerate_devices(instance_.get());
  available_devices_.clear();
  for (const PhysicalDevice& d : devices) {
    available_devices_.push_back(d.info);
  }
  const std::size_t chosen =
      select_device(std::span<const DeviceInfo>(available_devices_), DeviceRequest::parse(options.device));
  physical_device_ = devices[chosen].handle;
  device_info_ = devices[chosen].info;
  queue_family_ = devices[chosen].queue_family;
  vkGetPhysicalDeviceProperties(physical_device_, &properties_);
  limits_ = query_device_limits(physical_device_, queue_family_);
  vkGetPhysicalDeviceMemoryProperties(physical_device_, &memory_properties_);
}

void Context::create_device() {
  // What the device offers...
  VkPhysicalDeviceVulkan12Features supported12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  VkPhysicalDeviceFeatures2 supported{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  supported.pNext = &supported12;
  vkGetPhysicalDeviceFeatures2(physical_device_, &supported);

  // ... and what the runtime turns on: only what it uses, so that validation still flags a
  // pass that relies on a feature nobody enabled.
  VkPhysicalDeviceVulkan12Features enable12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  enable12.timelineSemaphore = VK_TRUE;  // checked by enumerate_devices()
  enable12.drawIndirectCount = supported12.drawIndirectCount;
  enable12.hostQueryReset = supported12.hostQueryReset;
  VkPhysicalDeviceFeatures2 enable{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  enable.pNext = &enable12;
  enable.features.multiDrawIndirect = supported.features.multiDrawIndirect;
  enable.features.sampleRateShading = supported.features.sampleRateShading;
  enable.features.depthClamp = supported.features.depthClamp;
  enable.features.fragmentStoresAndAtomics = supported.features.fragmentStoresAndAtomics;
  enable.features.largePoints = supported.features.largePoints;

  features_.draw_indirect_count = enable12.drawIndirectCount == VK_TRUE;
  features_.host_query_reset = enable12.hostQueryReset == VK_TRUE;
  features_.multi_draw_indirect = enable.features.multiDrawIndirect == VK_TRUE;
  features_.sample_rate_shading = enable.features.sampleRateShading == VK_TRUE;
  features_.depth_clamp = enable.features.depthClamp == VK_TRUE;
  features_.fragment_stores_and_atomics = enable.features.fragmentStoresAndAtomics == VK_TRUE;
  features_.large_points = enable.features.largePoints == VK_TRUE;
  std::vector<const char*> extensions;
  if (device_extension_available(physical_device_, VK_EXT_POST_DEPTH_COVERAGE_EXTENSION_NAME)) {
    extensions.push_back(VK_EXT_POST_DEPTH_COVERAGE_EXTENSION_NAME);
    features_.post_depth_coverage = true;
  }

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue_info{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue_info.queueFamilyIndex = queue_family_;
  queue_info.queueCount = 1;
  queue_info.pQueuePriorities = &priority;

  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  info.pNext = &enable;  // features go through pNext, so pEnabledFeatures stays null
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue_info;
  info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();

  VkDevice device = VK_NULL_HANDLE;
  check(vkCreateDevice(physical_device_, &info, nullptr, &device), "vkCreateDevice",
        fmt::format("the logical device on {}", device_info_.name));
  device_ = UniqueDevice(device, DeviceDeleter{});
  vkGetDeviceQueue(device, queue_family_, 0, &queue_);
  name_object(queue_, "main queue");

  const VkPipelineCacheCreateInfo cache_info{VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
  VkPipelineCache cache = VK_NULL_HANDLE;
  check(vkCreatePipelineCache(device, &cache_info, nullptr, &cache), "vkCreatePipelineCache", "the pipeline cache");
  pipeline_cache_ = UniquePipelineCache(cache, {device});
  name_object(cache, "pipeline cache");
}

VkSampleCountFlags Context::msaa_counts() const { return msaa_supported_counts(limits_); }

VkSampleCountFlagBits Context::choose_msaa(std::uint32_t requested) const {
  return tilelight::choose_msaa(msaa_counts(), requested);
}

void Context::set_object_name(VkObjectType type, std::uint64_t handle, std::string_view name) const {
  if (set_object_name_fn_ == nullptr || !device_ || name.empty()) {
    return;
  }
  const std::string copy(name);  // the API wants a NUL-terminated string
  VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
  info.objectType = type;
  info.objectHandle = handle;
  info.pObjectName = copy.c_str();
  check(set_object_name_fn_(device_.get(), &info), "vkSetDebugUtilsObjectNameEXT", copy);
}

void Context::wait_idle(std::string_view stage, Seconds timeout) const {
  VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VkFence raw = VK_NULL_HANDLE;
  check(vkCreateFence(device_.get(), &fence_info, nullptr, &raw), "vkCreateFence", stage);
  UniqueFence fence(raw, {device_.get()});
  // A submit with no batches signals its fence once all earlier submissions have completed.
  check(vkQueueSubmit(queue_, 0, nullptr, fence.get()), "vkQueueSubmit", stage);
  const VkResult result = vkWaitForFences(device_.get(), 1, &raw, VK_TRUE, timeout_ns(timeout));
  if (result == VK_TIMEOUT) {
    (void)fence.release();  // still pending on the queue; destroying it would be invalid
    throw_timeout(stage, timeout);
  }
  check(result, "vkWaitForFences", stage);
}

}  // namespace tilelight
