#pragma once
// The recording both GPU-driven builds share (the index build of the raster pass,
// gpu_index_build.h, and the tile-list build of the compute pass, gpu_tile_lists.h): clear the
// counters, count, prefix-sum, fill, make the results visible to the tile pass, and copy the
// counters to the host for the frame's statistics.

#include "tilelight/vulkan/buffer.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <string>

namespace tilelight {

class Context;

// What both builds read and count with besides their outputs.
struct ComputeBuildBuffers {
  Buffer lut;            // 256 uint32: raw ID byte -> draw class, 0xFF where impossible or out of range
  Buffer counters;       // counter_bytes, device-local; zeroed by record_compute_build()
  Buffer host_counters;  // the counters' host copy, read after the frame
};

// class_for_raw: raw ID -> draw class; pruned raw IDs (same size) map to 0xFF, as does every
// byte beyond them (the padding byte 0xFF of partial blocks included). `name` prefixes the
// buffers' debug names.
ComputeBuildBuffers create_compute_build_buffers(const Context& context, std::span<const std::uint8_t> class_for_raw,
                                                 std::span<const bool> pruned, VkDeviceSize counter_bytes,
                                                 const std::string& name);

struct ComputeBuildPasses {
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkDescriptorSet set = VK_NULL_HANDLE;  // set 0 of `layout`
  std::span<const std::uint32_t> push;   // the push constants of all three passes
  VkPipeline count = VK_NULL_HANDLE, prefix = VK_NULL_HANDLE, fill = VK_NULL_HANDLE;
  std::uint32_t groups = 0;            // workgroups of the count and fill passes
  VkBuffer counters = VK_NULL_HANDLE;  // zeroed first, then copied to host_counters
  VkBuffer host_counters = VK_NULL_HANDLE;
  VkDeviceSize counter_bytes = 0;
  // Where the tile pass reads the results: the draw stages' (raster) or the dispatch's (compute).
  VkPipelineStageFlags consumer_stages = 0;
  VkAccessFlags consumer_access = 0;
};

// Records the whole build; the prefix pass is one workgroup.
void record_compute_build(VkCommandBuffer cmd, const ComputeBuildPasses& build);

}  // namespace tilelight
