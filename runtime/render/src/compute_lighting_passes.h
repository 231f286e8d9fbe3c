#pragma once
// The global light pass in compute (--light-pass compute): the same permutations as the raster
// pass (lighting_passes.h), compiled from uber/lighting.comp (the "compute" uber-shader of
// permutations/split_second.json), dispatched instead of drawn. The tile pass is recorded ONCE,
// before any classification has run: per draw class, one pipeline bind, one push constant (the
// class) and one vkCmdDispatchIndirect whose VkDispatchIndirectCommand, and the class's tile list
// it shades, are written later each frame (by the host, or by the GPU-driven build). The naive
// and dynamic passes are one full-frame dispatch each (8x8 pixels a workgroup) of optimised ID
// 31 and of the per-pixel-branching build; the floor pass (where it runs) one more, of the
// floor build (no lighting), into its own target (floor_target.h).
//
// Every pass stores into its single-sampled light target as a storage image, in layout GENERAL
// while it runs, and leaves the target in TRANSFER_SRC_OPTIMAL, as the raster passes do.

#include "floor_target.h"
#include "lighting_interface.h"
#include "lighting_passes.h"
#include "render_targets.h"
#include "tilelight/tiles/tile_grid.h"
#include "tilelight/vulkan/buffer.h"
#include "tilelight/vulkan/vk_handles.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace tilelight {

class Context;
struct LightClasses;
class BranchSet;

class ComputeLightingPasses {
 public:
  // `tile_lists`: the buffer of per-class tile lists (uber/include/tile_lists.glsl) the tile pass
  // reads; it must outlive this object. `targets` must have storage light targets. `floor`: the
  // floor pass's target, or null where it does not run (no pipeline, no descriptor set).
  // `classes`: the tile pass's draw classes and the build they are dispatched with
  // (light_classes.h), `branch` that build's branch block (inactive without branch features):
  // both must outlive this object. The baselines dispatch the variant compute build.
  ComputeLightingPasses(const Context& context, const TileGrid& grid, const RenderTargets& targets,
                        const LightingInterface& lighting, const LightClasses& classes, const BranchSet& branch,
                        VkDescriptorPool pool, const Buffer& tile_lists, const FloorTarget* floor = nullptr);

  // 32 (optimised) or 128 (raw; the 32 pruned raw IDs have no pipeline and are never dispatched).
  std::uint32_t class_count() const { return static_cast<std::uint32_t>(class_pipelines_.size()); }
  std::uint32_t pipeline_count() const { return static_cast<std::uint32_t>(pipelines_.size()); }
  // Host milliseconds the tile pass's pipelines took to create.
  double tile_pipelines_ms() const { return tile_pipelines_ms_; }
  // Tiles one workgroup of the tile pass shades: 64 invocations over whole tiles.
  static std::uint32_t tiles_per_workgroup(std::uint32_t tile_size);

  // Before the timed passes: the classified target to GENERAL, cleared to magenta, so that a
  // pixel no dispatch wrote stands out and fails the equivalence test (the raster pass clears in
  // its render pass). A production renderer would skip it: every tile is some class's.
  void record_prepare(VkCommandBuffer cmd, const RenderTargets& targets) const;
  // The tile pass: starts with a barrier that makes host AND compute writes of the tile lists and
  // of `dispatches` visible to the indirect and compute stages, so the same recording serves the
  // CPU patching and the GPU-driven path. Precondition: record_prepare() earlier in `cmd`.
  void record_tiled(VkCommandBuffer cmd, const RenderTargets& targets, const Buffer& dispatches) const;
  void record_naive(VkCommandBuffer cmd, const RenderTargets& targets) const;
  void record_dynamic(VkCommandBuffer cmd, const RenderTargets& targets) const;
  // Precondition: constructed with this `floor`.
  void record_floor(VkCommandBuffer cmd, const FloorTarget& floor) const;

 private:
  void bind(VkCommandBuffer cmd, VkDescriptorSet target_set, VkPipelineLayout layout) const;
  void record_full_frame(VkCommandBuffer cmd, const Image& target, VkDescriptorSet target_set,
                         VkPipeline pipeline) const;

  const LightingInterface* lighting_;
  VkExtent2D extent_{};
  UniqueDescriptorSetLayout target_set_layout_;  // set 1: the light target and the tile lists
  UniquePipelineLayout layout_;
  const BranchSet* branch_;
  // The tile pass's layout: layout_, or with branch features its own, which adds the branch set.
  UniquePipelineLayout branch_layout_;
  VkPipelineLayout tile_layout_ = VK_NULL_HANDLE;
  std::vector<std::optional<std::uint32_t>> class_pipelines_;  // per draw class; none for pruned raw IDs
  double tile_pipelines_ms_ = 0;
  VkDescriptorSet classified_set_ = VK_NULL_HANDLE, naive_set_ = VK_NULL_HANDLE, dynamic_set_ = VK_NULL_HANDLE;
  VkDescriptorSet floor_set_ = VK_NULL_HANDLE;
  std::vector<UniquePipeline> pipelines_;  // the tile pass's (LightClasses::pipelines)
  UniquePipeline naive_pipeline_, dynamic_pipeline_, floor_pipeline_;
};

}  // namespace tilelight
