#pragma once
// The GPU-driven build of the compute light pass's work (--path gpu --light-pass compute): the
// LUT, per-class tile counts, the prefix sum, the tile lists and the indirect dispatch records,
// all in compute (uber/classify/tile_lists.comp). The twin of the CPU's TileListBuilder, as
// GpuIndexBuild is of TileIndexBuilder. No CPU round trip: the pre-recorded tile pass reads the
// buffers this fills.

#include "compute_build_passes.h"
#include "tilelight/tiles/tile_grid.h"
#include "tilelight/vulkan/buffer.h"

#include <shadergen/registry.h>

#include <cstdint>
#include <span>
#include <vector>

namespace tilelight {

class Context;

class GpuTileLists {
 public:
  // class_for_raw: raw ID -> draw class; pruned raw IDs are impossible. class_count: 32 or 128.
  // tiles_per_group: tiles one workgroup of the light pass shades. `shaders`: the compute light
  // registry (shader_registry.h), whose tile_lists companion it runs. `tile_ids`: the
  // classification's blocked raw IDs.
  GpuTileLists(const Context& context, const shadergen::Registry& shaders, const TileGrid& grid,
               std::span<const std::uint8_t> class_for_raw, std::span<const bool> pruned, std::uint32_t class_count,
               std::uint32_t tiles_per_group, const Buffer& tile_ids, VkDescriptorPool pool);

  // Clears the counters, counts, prefix-sums and fills; ends with a barrier that makes the lists
  // and the dispatch records visible to the indirect and compute stages.
  void record(VkCommandBuffer cmd) const;

  const Buffer& lists() const { return lists_; }
  const Buffer& dispatches() const { return dispatches_; }

  // Read back after the frame: tiles per class, and tiles with invalid IDs.
  struct Counts {
    std::vector<std::uint32_t> tiles;
    std::uint32_t invalid_tiles = 0;
  };
  Counts read_counts() const;

 private:
  std::uint32_t class_count_;
  Buffer lists_, dispatches_;
  ComputeBuild build_;
};

}  // namespace tilelight
