#pragma once
// The device limits the runtime's passes depend on, read once when the context is created.

#include <vulkan/vulkan.h>

#include <cstdint>

namespace tilelight {

struct DeviceLimits {
  std::uint32_t max_framebuffer_width = 0;
  std::uint32_t max_framebuffer_height = 0;
  std::uint32_t max_image_dimension_2d = 0;

  // Sample counts the device supports for each use; the G-buffer needs all four (it is
  // rendered as colour + depth attachments and then sampled by the lighting pass).
  VkSampleCountFlags framebuffer_color_samples = 0;
  VkSampleCountFlags framebuffer_depth_samples = 0;
  VkSampleCountFlags sampled_color_samples = 0;
  VkSampleCountFlags sampled_depth_samples = 0;

  float timestamp_period_ns = 0.0f;        // nanoseconds per timestamp tick
  std::uint32_t timestamp_valid_bits = 0;  // of the runtime's queue family; 0 = no timestamps

  std::uint32_t subgroup_size = 0;
  VkSubgroupFeatureFlags subgroup_operations = 0;
  VkShaderStageFlags subgroup_stages = 0;

  std::uint32_t max_push_constants_size = 0;
  std::uint32_t max_compute_workgroup_invocations = 0;
  std::uint32_t max_draw_indirect_count = 0;
  float max_point_size = 0.0f;  // pointSizeRange[1]
  std::uint32_t max_viewport_width = 0, max_viewport_height = 0;
  VkDeviceSize min_uniform_buffer_offset_alignment = 0;
  VkDeviceSize min_storage_buffer_offset_alignment = 0;
  VkDeviceSize non_coherent_atom_size = 0;
};

// Reads the limits of `device`; `queue_family` selects timestamp_valid_bits.
// Precondition: `device` supports Vulkan 1.1 or later (subgroup properties).
DeviceLimits query_device_limits(VkPhysicalDevice device, std::uint32_t queue_family);

}  // namespace tilelight
