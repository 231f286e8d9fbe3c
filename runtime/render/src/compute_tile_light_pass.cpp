#include "compute_tile_light_pass.h"

#include "shader_registry.h"
#include "tilelight/tiles/tile_index_builder.h"

#include <numeric>

namespace tilelight {

// The tile-list builder fills the mapped dispatch buffer through tiles' Vulkan-free DispatchRecord.
static_assert(sizeof(DispatchRecord) == sizeof(VkDispatchIndirectCommand));
static_assert(offsetof(DispatchRecord, x) == offsetof(VkDispatchIndirectCommand, x));
static_assert(offsetof(DispatchRecord, y) == offsetof(VkDispatchIndirectCommand, y));
static_assert(offsetof(DispatchRecord, z) == offsetof(VkDispatchIndirectCommand, z));

// The lists come first: the light pass's descriptor sets bind them.
ComputeTileLightPass::ComputeTileLightPass(const TileLightPassSetup& s)
    : TileLightPass(s), tiles_per_group_(ComputeLightingPasses::tiles_per_workgroup(s.grid.tile_size)) {
  const std::uint32_t classes = s.classes.class_count();
  const Buffer* lists = nullptr;
  if (s.path == IndexPath::cpu) {
    create_host_lists(s, classes);
    lists = &cpu_lists_;
    dispatches_ = &cpu_dispatches_;
  } else {
    gpu_lists_ =
        std::make_unique<GpuTileLists>(s.context, compute_shaders_for(s.targets.samples()), s.grid, s.class_for_raw,
                                       s.pruned, classes, tiles_per_group_, s.tile_ids, s.pool);
    lists = &gpu_lists_->lists();
    dispatches_ = &gpu_lists_->dispatches();
  }
  branch_ = std::make_unique<BranchSet>(s.context, s.classes, s.pool);
  passes_ = std::make_unique<ComputeLightingPasses>(s.context, s.grid, s.targets, s.lighting, s.classes, *branch_,
                                                    s.pool, *lists, s.floor);
}

void ComputeTileLightPass::create_host_lists(const TileLightPassSetup& s, std::uint32_t classes) {
  cpu_builder_ = std::make_unique<TileListBuilder>(s.grid, s.class_for_raw, s.pruned, classes, tiles_per_group_);
  cpu_lists_ =
      Buffer(s.context, {(kTileListHeaderWords + std::size_t{s.grid.tile_count()}) * sizeof(std::uint32_t),
                         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::HostUpload, "tile lists (host-built)"});
  cpu_dispatches_ = Buffer(s.context, {classes * sizeof(VkDispatchIndirectCommand), VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT,
                                       MemoryUse::HostUpload, "indirect dispatches (host-patched)"});
  clear_draws();
}

void ComputeTileLightPass::record_build(VkCommandBuffer cmd) const { gpu_lists_->record(cmd); }

void ComputeTileLightPass::record_prepare(VkCommandBuffer cmd, const RenderTargets& targets) const {
  passes_->record_prepare(cmd, targets);
}

void ComputeTileLightPass::record_tiled(VkCommandBuffer cmd, const RenderTargets& targets) const {
  passes_->record_tiled(cmd, targets, *dispatches_);
}

void ComputeTileLightPass::record_baseline(VkCommandBuffer cmd, const RenderTargets& targets, BaselinePass pass) const {
  switch (pass) {
    case BaselinePass::naive: return passes_->record_naive(cmd, targets);
    case BaselinePass::dynamic: return passes_->record_dynamic(cmd, targets);
    case BaselinePass::floor: return passes_->record_floor(cmd, floor());
  }
}

void ComputeTileLightPass::build_on_host(std::span<const std::uint8_t> blocked_raw_ids) {
  built_ = cpu_builder_->build(blocked_raw_ids, cpu_lists_.as<std::uint32_t>(), cpu_dispatches_.as<DispatchRecord>());
}

void ComputeTileLightPass::clear_draws() {
  if (!host_builds()) return;  // the GPU build writes every record itself
  for (DispatchRecord& d : cpu_dispatches_.as<DispatchRecord>()) d = {0, 1, 1};
}

FrameStats ComputeTileLightPass::stats() const {
  if (host_builds()) return list_stats(std::span(built_.class_tiles).first(class_count()));
  const GpuTileLists::Counts counts = gpu_lists_->read_counts();
  check_no_invalid_tiles(counts.invalid_tiles, "GPU-driven tile-list build");
  return list_stats(counts.tiles);
}

FrameStats ComputeTileLightPass::list_stats(std::span<const std::uint32_t> class_tiles) const {
  FrameStats stats;
  stats.class_tiles.assign(class_tiles.begin(), class_tiles.end());
  stats.class_rectangles.assign(class_tiles.size(), 0);
  for (const std::uint32_t tiles : class_tiles) {
    stats.class_primitives.push_back((tiles + tiles_per_group_ - 1) / tiles_per_group_);
  }
  stats.primitives_uncoalesced = std::accumulate(class_tiles.begin(), class_tiles.end(), 0u);
  stats.primitives_coalesced = std::accumulate(stats.class_primitives.begin(), stats.class_primitives.end(), 0u);
  return stats;
}

}  // namespace tilelight
