#pragma once
// The light passes as dispatches (LightPass::compute): ComputeLightingPasses, fed by per-class
// tile lists and one indirect dispatch per class, which the host's TileListBuilder writes into
// host-visible coherent memory after the tile pass was submitted (IndexPath::cpu) or
// GpuTileLists writes in submit A (IndexPath::gpu). The path is chosen at construction.

#include "branch_set.h"
#include "compute_lighting_passes.h"
#include "gpu_tile_lists.h"
#include "tile_light_pass.h"
#include "tilelight/tiles/tile_list_builder.h"
#include "tilelight/vulkan/buffer.h"

#include <memory>

namespace tilelight {

class ComputeTileLightPass final : public TileLightPass {
 public:
  // Precondition: setup.targets has storage light targets.
  explicit ComputeTileLightPass(const TileLightPassSetup& setup);

  std::uint32_t class_count() const override { return passes_->class_count(); }
  std::uint32_t pipeline_count() const override { return passes_->pipeline_count(); }
  double tile_pipelines_ms() const override { return passes_->tile_pipelines_ms(); }

  void record_build(VkCommandBuffer cmd) const override;
  void record_prepare(VkCommandBuffer cmd, const RenderTargets& targets) const override;
  void record_tiled(VkCommandBuffer cmd, const RenderTargets& targets) const override;
  void record_baseline(VkCommandBuffer cmd, const RenderTargets& targets, BaselinePass pass) const override;

  void build_on_host(std::span<const std::uint8_t> blocked_raw_ids) override;
  void clear_draws() override;
  FrameStats stats() const override;

 private:
  void create_host_lists(const TileLightPassSetup& setup, std::uint32_t classes);
  // Tiles per class, and the workgroups that shade them.
  FrameStats list_stats(std::span<const std::uint32_t> class_tiles) const;

  std::uint32_t tiles_per_group_;
  // IndexPath::cpu: the builder, the tile lists, one dispatch record per class, and the figures
  // of the last build.
  std::unique_ptr<TileListBuilder> cpu_builder_;
  Buffer cpu_lists_, cpu_dispatches_;
  TileListStats built_{};
  std::unique_ptr<GpuTileLists> gpu_lists_;  // IndexPath::gpu
  const Buffer* dispatches_ = nullptr;       // the CPU path's or the GPU build's
  // Declared after the lists and the branch set it binds, so that it is destroyed first.
  std::unique_ptr<BranchSet> branch_;
  std::unique_ptr<ComputeLightingPasses> passes_;
};

}  // namespace tilelight
