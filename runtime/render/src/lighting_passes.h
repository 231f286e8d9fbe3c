#pragma once
// The global light pass, tiled and naive. The tiled pass is recorded ONCE, before any
// classification has run (Split/Second, Sections 4.7 and 4.9): one pipeline bind and one
// indirect indexed draw per draw class, reading index and indirect buffers that are filled in
// later each frame (by the host, or by the GPU-driven build). Its primitives are triangle pairs
// or point sprites (tile_primitive.h). The naive pass draws optimised ID 31 (every feature) over
// the whole frame as two triangles; the dynamic pass draws the per-pixel-branching build of the
// uber-shader (companion lighting_dynamic: every feature, each taken where the pixel needs it)
// the same way, the baseline that tile classification must beat on a real engine.

#include "floor_target.h"
#include "lighting_interface.h"
#include "render_targets.h"
#include "tilelight/tiles/tile_grid.h"
#include "tilelight/tiles/tile_primitive.h"
#include "tilelight/vulkan/buffer.h"
#include "tilelight/vulkan/vk_handles.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace tilelight {

class Context;

enum class PermutationSet { optimised, raw };

struct LightClasses;
class BranchSet;

class LightingPasses {
 public:
  // `classes`: the tile pass's draw classes and the build they are drawn with (light_classes.h);
  // `branch`: that build's branch block (inactive without branch features). Both must outlive
  // this object. The baselines draw the variant build of lighting.shaders(). `floor`: build the
  // floor pass's pipeline (only a renderer that runs it pays for it).
  LightingPasses(const Context& context, const TileGrid& grid, const RenderTargets& targets,
                 const LightingInterface& lighting, const LightClasses& classes, const BranchSet& branch,
                 TilePrimitive primitive, bool floor = false);

  // 32 (optimised) or 128 (raw; the 32 pruned raw IDs have no pipeline and are never drawn).
  std::uint32_t class_count() const { return static_cast<std::uint32_t>(class_pipelines_.size()); }
  std::uint32_t pipeline_count() const { return static_cast<std::uint32_t>(pipelines_.size()); }
  // Host milliseconds the tile pass's pipelines took to create.
  double tile_pipelines_ms() const { return tile_pipelines_ms_; }

  // The tile pass: starts with a barrier that makes host AND compute writes of `indices` and
  // `draws` visible to the draw stages, so the same recording serves the CPU patching and the
  // GPU-driven path.
  void record_tiled(VkCommandBuffer cmd, const RenderTargets& targets, const Buffer& indices,
                    const Buffer& draws) const;
  void record_naive(VkCommandBuffer cmd, const RenderTargets& targets) const;
  void record_dynamic(VkCommandBuffer cmd, const RenderTargets& targets) const;
  // Precondition: constructed with `floor`.
  void record_floor(VkCommandBuffer cmd, const RenderTargets& targets, const FloorTarget& floor) const;

 private:
  void begin(VkCommandBuffer cmd, const RenderTargets& targets, VkFramebuffer framebuffer,
             VkPipelineLayout layout) const;
  void record_full_screen(VkCommandBuffer cmd, const RenderTargets& targets, VkFramebuffer framebuffer,
                          VkPipeline pipeline) const;

  const LightingInterface* lighting_;
  const BranchSet* branch_;
  // The tile pass's layout: the lighting layout, or with branch features its own, which adds
  // the branch set (set 1 an empty one).
  UniquePipelineLayout branch_layout_;
  VkPipelineLayout tile_layout_ = VK_NULL_HANDLE;
  std::vector<std::optional<std::uint32_t>> class_pipelines_;  // per draw class; none for pruned raw IDs
  double tile_pipelines_ms_ = 0;
  Buffer corners_;                         // the prebuilt grid of tile corners (pixels): triangles
  Buffer grid_shape_;                      // tiles_x + 1 and the tile size: points
  Buffer full_screen_indices_;             // two triangles over the whole frame (naive and dynamic passes)
  std::vector<UniquePipeline> pipelines_;  // the tile pass's (LightClasses::pipelines)
  UniquePipeline naive_pipeline_, dynamic_pipeline_, floor_pipeline_;
  VkExtent2D extent_{};    // the frame
  VkExtent2D viewport_{};  // whole tiles: >= the frame
};

}  // namespace tilelight
