#include "tilelight/vulkan/device_limits.h"

#include <vector>

namespace tilelight {

DeviceLimits query_device_limits(VkPhysicalDevice device, std::uint32_t queue_family) {
  VkPhysicalDeviceSubgroupProperties subgroup{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
  VkPhysicalDeviceProperties2 props2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  props2.pNext = &subgroup;
  vkGetPhysicalDeviceProperties2(device, &props2);
  const VkPhysicalDeviceLimits& l = props2.properties.limits;

  std::uint32_t family_count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device, &family_count, nullptr);
  std::vector<VkQueueFamilyProperties> families(family_count);
  vkGetPhysicalDeviceQueueFamilyProperties(device, &family_count, families.data());

  DeviceLimits limits;
  limits.max_framebuffer_width = l.maxFramebufferWidth;
  limits.max_framebuffer_height = l.maxFramebufferHeight;
  limits.max_image_dimension_2d = l.maxImageDimension2D;
  limits.framebuffer_color_samples = l.framebufferColorSampleCounts;
  limits.framebuffer_depth_samples = l.framebufferDepthSampleCounts;
  limits.sampled_color_samples = l.sampledImageColorSampleCounts;
  limits.sampled_depth_samples = l.sampledImageDepthSampleCounts;
  limits.timestamp_period_ns = l.timestampPeriod;
  limits.timestamp_valid_bits = queue_family < family_count ? families[queue_family].timestampValidBits : 0;
  limits.subgroup_size = subgroup.subgroupSize;
  limits.subgroup_operations = subgroup.supportedOperations;
  limits.subgroup_stages = subgroup.supportedStages;
  limits.max_push_constants_size = l.maxPushConstantsSize;
  limits.max_compute_workgroup_invocations = l.maxComputeWorkGroupInvocations;
  limits.max_draw_indirect_count = l.maxDrawIndirectCount;
  limits.max_point_size = l.pointSizeRange[1];
  limits.max_viewport_width = l.maxViewportDimensions[0];
  limits.max_viewport_height = l.maxViewportDimensions[1];
  limits.min_uniform_buffer_offset_alignment = l.minUniformBufferOffsetAlignment;
  limits.min_storage_buffer_offset_alignment = l.minStorageBufferOffsetAlignment;
  limits.non_coherent_atom_size = l.nonCoherentAtomSize;
  return limits;
}

}  // namespace tilelight
