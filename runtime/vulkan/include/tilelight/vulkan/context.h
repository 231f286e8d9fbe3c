#pragma once
// The Vulkan context: instance (+ validation), the chosen physical device, the logical device
// and its one queue. Headless: no surface, no swapchain; everything is read back.

#include "tilelight/vulkan/device_limits.h"
#include "tilelight/vulkan/device_selection.h"
#include "tilelight/vulkan/object_type.h"
#include "tilelight/vulkan/timeout.h"
#include "tilelight/vulkan/validation.h"
#include "tilelight/vulkan/vk_handles.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace tilelight {

struct ContextOptions {
  // "" = default (lavapipe, "llvmpipe", if present; see select_device()), all digits = device
  // index, anything else = case-insensitive substring of the device name.
  std::string device;
  // Enables VK_LAYER_KHRONOS_validation with a messenger that records every warning and error
  // (see require_no_validation_messages()). Throws if the layer is not installed.
  bool validation = false;
  // Also enables the layer's synchronization validation (hazards between commands). Requires
  // `validation`. Slow; for tests of the synchronisation code.
  bool synchronization_validation = false;
  std::string application_name = "tilelight";
};

// Optional device features, enabled when the device supports them. Timeline semaphores are
// required and therefore not listed.
struct EnabledFeatures {
  bool draw_indirect_count = false;  // vkCmdDrawIndexedIndirectCount
  bool multi_draw_indirect = false;  // drawCount > 1 in one indirect call
  bool host_query_reset = false;     // vkResetQueryPool from the host
  bool sample_rate_shading = false;
  bool depth_clamp = false;  // shadow-map rendering
  bool fragment_stores_and_atomics = false;
  bool large_points = false;         // point sprites wider than 1 pixel: the tile pass's points
  bool post_depth_coverage = false;  // VK_EXT_post_depth_coverage: the G-buffer's coverage flags
};

class Context {
 public:
  // Creates everything; throws tilelight::Error / VulkanError with what failed.
  explicit Context(const ContextOptions& options = {});
  // Waits (bounded, 10 s) for the queue to drain, then destroys the device and instance. If the
  // queue does not drain (a submit waiting on a host signal that never came), it reports that
  // on stderr and leaks the device rather than destroying objects the GPU still uses or
  // blocking forever. Precondition: every object created from this context is destroyed first.
  ~Context();

  // Not movable: the validation layer holds a pointer to the log, and resources keep the raw
  // VkDevice. Hold a Context in a std::unique_ptr where it must move.
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;
  Context(Context&&) = delete;
  Context& operator=(Context&&) = delete;

  VkInstance instance() const { return instance_.get(); }
  VkPhysicalDevice physical_device() const { return physical_device_; }
  VkDevice device() const { return device_.get(); }
  // One pipeline cache for every pipeline made on this device: a renderer builds up to 96 light
  // pipelines (raw permutations) and several renderers of one process (tests, the sweep) build
  // the same ones again; the driver then compiles each shader once.
  VkPipelineCache pipeline_cache() const { return pipeline_cache_.get(); }
  // The one queue (graphics + compute + transfer). Vulkan requires external synchronisation:
  // submit from one thread at a time.
  VkQueue queue() const { return queue_; }
  std::uint32_t queue_family() const { return queue_family_; }

  const DeviceInfo& device_info() const { return device_info_; }
  const std::string& device_name() const { return device_info_.name; }
  // Every device the instance enumerated, as selection saw them.
  const std::vector<DeviceInfo>& available_devices() const { return available_devices_; }
  const VkPhysicalDeviceProperties& properties() const { return properties_; }
  const DeviceLimits& limits() const { return limits_; }
  const EnabledFeatures& features() const { return features_; }
  const VkPhysicalDeviceMemoryProperties& memory_properties() const { return memory_properties_; }

  // Sample counts usable for the G-buffer (msaa_supported_counts() of limits()).
  VkSampleCountFlags msaa_counts() const;
  // choose_msaa() (msaa.h) on this device's sample counts.
  VkSampleCountFlagBits choose_msaa(std::uint32_t requested) const;

  bool validation_enabled() const { return validation_; }
  // Throws tilelight::Error listing the messages if the layer reported any.
  void require_no_validation_messages(std::string_view stage) const { log_->require_empty(stage); }

  // Gives a Vulkan object a debug name that validation messages quote. No-op without
  // validation.
  void set_object_name(VkObjectType type, std::uint64_t handle, std::string_view name) const;
  template <typename T>
  void name_object(T handle, std::string_view name) const {
    // Every handle is a pointer on the (64-bit) targets object_type.h admits.
    set_object_name(ObjectType<T>::value, reinterpret_cast<std::uint64_t>(handle), name);
  }

  // Waits until everything submitted to the queue so far has finished, with a timeout (an
  // empty submit with a fence; vkQueueWaitIdle has no timeout). Never call this while a
  // submitted batch waits on a host signal that the calling thread has yet to give: it would
  // wait on itself until the timeout.
  void wait_idle(std::string_view stage, Seconds timeout = kDefaultGpuTimeout) const;

 private:
  // The tests' way to the validation log itself (tests/support/tilelight_testing/
  // context_test_seam.h); the product only asks require_no_validation_messages().
  friend class ContextTestSeam;

  // Warnings and errors from the validation layer (always empty when validation is off). The
  // shared form outlives the context, so messages emitted while it is destroyed (leaked
  // objects) can still be checked.
  ValidationLog& validation_log() const { return *log_; }
  std::shared_ptr<const ValidationLog> shared_validation_log() const { return log_; }

  void create_instance(const ContextOptions& options);
  void create_validation_messenger();
  void pick_device(const ContextOptions& options);
  void create_device();

  std::shared_ptr<ValidationLog> log_;
  bool validation_ = false;
  UniqueInstance instance_;
  UniqueDebugMessenger messenger_;
  PFN_vkSetDebugUtilsObjectNameEXT set_object_name_fn_ = nullptr;

  VkPhysicalDevice physical_device_ = VK_NULL_HANDLE;
  DeviceInfo device_info_;
  VkPhysicalDeviceProperties properties_{};
  std::vector<DeviceInfo> available_devices_;
  std::uint32_t queue_family_ = 0;
  DeviceLimits limits_;
  EnabledFeatures features_;
  VkPhysicalDeviceMemoryProperties memory_properties_{};

  UniqueDevice device_;
  UniquePipelineCache pipeline_cache_;  // after device_: destroyed before it
  VkQueue queue_ = VK_NULL_HANDLE;
};

}  // namespace tilelight
