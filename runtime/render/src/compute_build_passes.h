#pragma once
// What both GPU-driven builds share (the index build of the raster pass, gpu_index_build.h, and
// the tile-list build of the compute pass, gpu_tile_lists.h): the class LUT and the counters,
// one descriptor set of five storage buffers and the pipeline layout (both from the passes'
// reflection), the count, prefix-sum and fill pipelines, and the recording: clear the counters,
// count, prefix-sum, fill, make the results visible to the tile pass, and copy the counters to
// the host for the frame's statistics. Each build says only what differs: its shaders and
// specialisation, its two outputs, its push constants and its consumers.

#include "pipelines.h"
#include "tilelight/vulkan/barriers.h"
#include "tilelight/vulkan/buffer.h"
#include "tilelight/vulkan/vk_handles.h"

#include <shadergen/registry.h>
#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace tilelight {

class Context;

// One of the three passes: a companion shader (its SPIR-V and reflection) and its specialisation.
struct ComputeBuildPass {
  const shadergen::Permutation* shader = nullptr;
  SpecConstants constants;
};

// What every build reads: the classification's tile IDs and the draw class of each raw ID.
struct ComputeBuildInput {
  VkBuffer tile_ids = VK_NULL_HANDLE;  // blocked raw IDs (classify_tiles.comp)
  // Raw ID -> draw class; pruned raw IDs (same size) map to 0xFF, as does every byte beyond
  // them (the padding byte 0xFF of partial blocks included).
  std::span<const std::uint8_t> class_for_raw;
  std::span<const bool> pruned;
};

// What makes one build: its shaders, outputs, push constants and consumers.
struct ComputeBuildDesc {
  std::string name;                // "GPU index build": prefixes every debug name
  VkDeviceSize counter_bytes = 0;  // the shaders' Counters block
  // Set 0 binds the input's tile IDs, the LUT and the counters at bindings 0..2, these at 3 and 4.
  std::array<VkBuffer, 2> outputs{};
  ComputeBuildPass count, prefix, fill;
  std::vector<std::uint32_t> push;  // the push constants of all three passes
  std::uint32_t groups = 0;         // workgroups of the count and fill passes; prefix is one
  // Where the tile pass reads the results: the draw stages (raster) or the dispatch (compute).
  Scope consumer;
};

// The workgroups of `pass` (a compute shader: its reflected local_size_x is at least 1) that
// give `invocations` invocations along x: the shader, not the C++, says how many a group runs.
std::uint32_t workgroups(std::uint32_t invocations, const shadergen::Permutation& pass);

class ComputeBuild {
 public:
  ComputeBuild() = default;  // empty: record() may not be called
  // Preconditions: every pass's shader is set (a compute companion); input.class_for_raw and
  // input.pruned have one size, at most 256. Throws tilelight::Error when the passes' reflection
  // disagrees with `desc`: bindings other than five storage buffers in set 0, or a push-constant
  // block of another size than `push`.
  ComputeBuild(const Context& context, VkDescriptorPool pool, const ComputeBuildInput& input, ComputeBuildDesc desc);

  void record(VkCommandBuffer cmd) const;

  // The counters as the last recorded build left them; read after its submit completed.
  std::span<const std::uint32_t> host_counters() const { return host_counters_.as<const std::uint32_t>(); }

 private:
  void create_buffers(const Context& context, const ComputeBuildInput& input, const std::string& name);
  void create_layout(const Context& context, const ComputeBuildDesc& desc);

  Buffer lut_;            // 256 uint32: raw ID byte -> draw class, 0xFF where impossible or out of range
  Buffer counters_;       // device-local; zeroed by record()
  Buffer host_counters_;  // the counters' host copy
  UniqueDescriptorSetLayout set_layout_;
  UniquePipelineLayout layout_;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  UniquePipeline count_, prefix_, fill_;
  std::vector<std::uint32_t> push_;
  std::uint32_t groups_ = 0;
  VkDeviceSize counter_bytes_ = 0;
  Scope consumer_;
};

}  // namespace tilelight
