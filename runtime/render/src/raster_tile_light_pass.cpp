#include "raster_tile_light_pass.h"

#include <algorithm>
#include <numeric>

namespace tilelight {

// The CPU index builder fills the mapped indirect buffer through tiles' Vulkan-free DrawRecord.
static_assert(sizeof(DrawRecord) == sizeof(VkDrawIndexedIndirectCommand));
static_assert(offsetof(DrawRecord, indexCount) == offsetof(VkDrawIndexedIndirectCommand, indexCount));
static_assert(offsetof(DrawRecord, instanceCount) == offsetof(VkDrawIndexedIndirectCommand, instanceCount));
static_assert(offsetof(DrawRecord, firstIndex) == offsetof(VkDrawIndexedIndirectCommand, firstIndex));
static_assert(offsetof(DrawRecord, vertexOffset) == offsetof(VkDrawIndexedIndirectCommand, vertexOffset));
static_assert(offsetof(DrawRecord, firstInstance) == offsetof(VkDrawIndexedIndirectCommand, firstInstance));

RasterTileLightPass::RasterTileLightPass(const TileLightPassSetup& s)
    : TileLightPass(s),
      branch_(s.context, s.classes, s.pool),
      passes_(s.context, s.grid, s.targets, s.lighting, s.classes, branch_, s.primitive, s.floor != nullptr),
      coalesce_(s.coalesce) {
  const std::uint32_t classes = passes_.class_count();
  if (s.path == IndexPath::cpu) {
    cpu_builder_ = std::make_unique<TileIndexBuilder>(s.grid, s.class_for_raw, s.pruned, classes, s.primitive);
    cpu_indices_ =
        Buffer(s.context, {std::max<VkDeviceSize>(s.grid.max_index_count(), 6) * sizeof(std::uint32_t),
                           VK_BUFFER_USAGE_INDEX_BUFFER_BIT, MemoryUse::HostUpload, "tile indices (host-built)"});
    cpu_draws_ = Buffer(s.context, {classes * sizeof(VkDrawIndexedIndirectCommand), VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT,
                                    MemoryUse::HostUpload, "indirect draws (host-patched)"});
    clear_draws();
    indices_ = &cpu_indices_;
    draws_ = &cpu_draws_;
  } else {
    gpu_build_ = std::make_unique<GpuIndexBuild>(s.context, s.lighting.shaders(), s.grid, s.class_for_raw, s.pruned,
                                                 classes, s.coalesce, s.primitive, s.tile_ids, s.pool);
    indices_ = &gpu_build_->indices();
    draws_ = &gpu_build_->draws();
  }
}

void RasterTileLightPass::record_build(VkCommandBuffer cmd) const { gpu_build_->record(cmd); }

void RasterTileLightPass::record_tiled(VkCommandBuffer cmd, const RenderTargets& targets) const {
  passes_.record_tiled(cmd, targets, *indices_, *draws_);
}

void RasterTileLightPass::record_baseline(VkCommandBuffer cmd, const RenderTargets& targets, BaselinePass pass) const {
  switch (pass) {
    case BaselinePass::naive: return passes_.record_naive(cmd, targets);
    case BaselinePass::dynamic: return passes_.record_dynamic(cmd, targets);
    case BaselinePass::floor: return passes_.record_floor(cmd, targets, floor());
  }
}

void RasterTileLightPass::build_on_host(std::span<const std::uint8_t> blocked_raw_ids) {
  built_ =
      cpu_builder_->build(blocked_raw_ids, coalesce_, cpu_indices_.as<std::uint32_t>(), cpu_draws_.as<DrawRecord>());
}

void RasterTileLightPass::clear_draws() {
  if (!host_builds()) return;  // the GPU build writes every record itself
  for (DrawRecord& d : cpu_draws_.as<DrawRecord>()) d = {0, 1, 0, 0, 0};
}

FrameStats RasterTileLightPass::stats() const { return host_builds() ? host_stats() : gpu_stats(); }

FrameStats RasterTileLightPass::host_stats() const {
  // One entry per draw class, like the GPU path's counts.
  const std::size_t classes = class_count();
  FrameStats stats;
  stats.class_tiles.assign(built_.class_tiles.begin(), built_.class_tiles.begin() + classes);
  stats.class_rectangles.assign(built_.rectangles.begin(), built_.rectangles.begin() + classes);
  stats.class_primitives.assign(built_.primitives.begin(), built_.primitives.begin() + classes);
  stats.primitives_uncoalesced = built_.primitives_uncoalesced;
  stats.primitives_coalesced = built_.primitives_coalesced;
  stats.rectangles = built_.rectangles_coalesced;
  return stats;
}

FrameStats RasterTileLightPass::gpu_stats() const {
  const GpuIndexBuild::Counts counts = gpu_build_->read_counts();
  check_no_invalid_tiles(counts.invalid_tiles, "GPU-driven index build");
  FrameStats stats;
  stats.class_tiles = counts.tiles;
  stats.class_rectangles = counts.rectangles;
  stats.class_primitives = counts.primitives;
  stats.primitives_uncoalesced = std::accumulate(counts.tiles.begin(), counts.tiles.end(), 0u);
  stats.primitives_coalesced = std::accumulate(counts.primitives.begin(), counts.primitives.end(), 0u);
  stats.rectangles = std::accumulate(counts.rectangles.begin(), counts.rectangles.end(), 0u);
  return stats;
}

}  // namespace tilelight
