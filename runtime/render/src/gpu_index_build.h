#pragma once
// The GPU-driven index build (--path gpu): the LUT, per-class counts, the prefix sum, the index
// fill and the indirect records, all in compute (uber/classify/tile_rects.comp and
// tile_prefix.comp), with the same coalescing rule as the CPU builder. No CPU round trip: the
// pre-recorded tile pass reads the buffers this fills.

#include "compute_build_passes.h"
#include "tilelight/tiles/tile_grid.h"
#include "tilelight/tiles/tile_primitive.h"
#include "tilelight/vulkan/buffer.h"

#include <shadergen/registry.h>

#include <cstdint>
#include <span>

namespace tilelight {

class Context;

class GpuIndexBuild {
 public:
  // class_for_raw: raw ID -> draw class (optimised ID, or the raw ID for raw permutations);
  // pruned raw IDs are impossible. class_count: 32 or 128. `shaders`: the frame's registry
  // (shader_registry.h), whose tile_rects and tile_prefix companions it runs.
  GpuIndexBuild(const Context& context, const shadergen::Registry& shaders, const TileGrid& grid,
                std::span<const std::uint8_t> class_for_raw, std::span<const bool> pruned, std::uint32_t class_count,
                bool coalesce, TilePrimitive primitive, const Buffer& tile_ids, VkDescriptorPool pool);

  // Clears the counters, counts, prefix-sums and fills; ends with a barrier that makes the
  // index buffer and the indirect records visible to the draw stages.
  void record(VkCommandBuffer cmd) const;

  const Buffer& indices() const { return indices_; }
  const Buffer& draws() const { return draws_; }

  // Read back after the frame: primitives, rectangles and tiles per class, and tiles with invalid IDs.
  struct Counts {
    std::vector<std::uint32_t> primitives, rectangles, tiles;
    std::uint32_t invalid_tiles = 0;
  };
  Counts read_counts() const;

 private:
  std::uint32_t class_count_;
  Buffer indices_, draws_;
  ComputeBuild build_;
};

}  // namespace tilelight
