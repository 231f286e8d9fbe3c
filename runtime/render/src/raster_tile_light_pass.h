#pragma once
// The light passes as draws (LightPass::raster): LightingPasses, fed by an index buffer and one
// indirect draw per class, which the host's TileIndexBuilder writes into host-visible coherent
// memory after the tile pass was submitted (IndexPath::cpu) or GpuIndexBuild writes in submit A
// (IndexPath::gpu). The path is chosen at construction.

#include "branch_set.h"
#include "gpu_index_build.h"
#include "lighting_passes.h"
#include "tile_light_pass.h"
#include "tilelight/tiles/tile_index_builder.h"
#include "tilelight/vulkan/buffer.h"

#include <memory>

namespace tilelight {

class RasterTileLightPass final : public TileLightPass {
 public:
  explicit RasterTileLightPass(const TileLightPassSetup& setup);

  std::uint32_t class_count() const override { return passes_.class_count(); }
  std::uint32_t pipeline_count() const override { return passes_.pipeline_count(); }
  double tile_pipelines_ms() const override { return passes_.tile_pipelines_ms(); }

  void record_build(VkCommandBuffer cmd) const override;
  void record_tiled(VkCommandBuffer cmd, const RenderTargets& targets) const override;
  void record_baseline(VkCommandBuffer cmd, const RenderTargets& targets, BaselinePass pass) const override;

  void build_on_host(std::span<const std::uint8_t> blocked_raw_ids) override;
  void clear_draws() override;
  FrameStats stats() const override;

 private:
  FrameStats host_stats() const;
  FrameStats gpu_stats() const;

  BranchSet branch_;  // before the passes that bind it
  LightingPasses passes_;
  bool coalesce_;
  // IndexPath::cpu: the builder, one preallocated index buffer, one indirect record per class,
  // and the figures of the last build.
  std::unique_ptr<TileIndexBuilder> cpu_builder_;
  Buffer cpu_indices_, cpu_draws_;
  IndexBuildStats built_{};
  std::unique_ptr<GpuIndexBuild> gpu_build_;  // IndexPath::gpu
  // What the tile pass draws from: the CPU path's buffers or the GPU build's.
  const Buffer* indices_ = nullptr;
  const Buffer* draws_ = nullptr;
};

}  // namespace tilelight
