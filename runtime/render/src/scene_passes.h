#pragma once
// The scene passes: the sun shadow map (depth only) and the G-buffer (materials, then sky).
// Blended meshes (Mesh::blend) are in neither: the forward pass draws them (forward_pass.h).
// Meshes, instances and base colour textures are uploaded once; the camera is fixed per renderer.

#include "render_targets.h"
#include "scene_textures.h"
#include "tilelight/scene/batch_culling.h"
#include "tilelight/scene/scene.h"
#include "tilelight/scene/uniform_blocks.h"
#include "tilelight/vulkan/buffer.h"
#include "tilelight/vulkan/vk_handles.h"

#include <array>
#include <cstddef>
#include <vector>

namespace shadergen {
struct Registry;
}

namespace tilelight {

class CommandPool;
class Context;

class ScenePasses {
 public:
  // `upload_pool` records the texture uploads (waited for before this returns). With `cull`,
  // each pass skips the batches wholly outside its clip volume (batch_culling.h).
  ScenePasses(const Context& context, const Scene& scene, const Camera& camera, const RenderTargets& targets,
              VkDescriptorPool pool, const CommandPool& upload_pool, bool cull);

  // Batches the G-buffer passes and the shadow-map pass skip (0 without culling).
  std::uint32_t culled_gbuffer_batches() const { return gbuffer_batches_.culled; }
  std::uint32_t culled_shadow_batches() const { return shadow_batches_.culled; }
  // Binds mesh `mesh`'s vertices (binding 0) beside `instances` (binding 1) and its indices, as
  // uploaded here for every mesh of the scene, blended ones included (the forward pass draws
  // those from these buffers); returns its index count.
  std::uint32_t bind_mesh(VkCommandBuffer cmd, std::uint32_t mesh, VkBuffer instances) const;
  // The scene's textures (the local lights' globe maps bind their sets).
  const SceneTextures& textures() const { return textures_; }

  // Shadow map pass, then the classified path's G-buffer pass (geometry, then sky at the far
  // plane), with the coverage flags where the targets have them.
  void record_shadow_map(VkCommandBuffer cmd, const RenderTargets& targets) const;
  void record_gbuffer(VkCommandBuffer cmd, const RenderTargets& targets) const;
  // The baselines' plain G-buffer: what lighting reads and nothing else (no classification data),
  // into the same targets, bit-identical in every target lighting reads.
  void record_gbuffer_plain(VkCommandBuffer cmd, const RenderTargets& targets) const;

  // The local lights' shadow maps (local_light_shadows.cpp): every batch `drawn` keeps whose mesh
  // is alpha-masked (`masked`) or not, with the caller's pipeline bound, in scene order; a masked
  // mesh's base colour texture is bound as set `texture_set` of `layout` first. Precondition:
  // `drawn` has one entry per batch of the scene.
  void draw_casters(VkCommandBuffer cmd, bool masked, const std::vector<bool>& drawn, VkPipelineLayout layout,
                    std::uint32_t texture_set) const;
  // Whether the scene has masked (or unmasked) meshes in some batch.
  bool draws_casters(bool masked) const { return kind_drawn_[masked ? 2 : 0] || kind_drawn_[masked ? 3 : 1]; }

 private:
  // What a batch's pipelines depend on (batch_kind()): alpha-masked or not, single-sided (back
  // faces culled) or not. Batches are drawn kind by kind, each in scene order, so the procedural
  // scene (kind 0 only) draws as it always did; only the kinds a scene has get pipelines.
  static constexpr std::size_t kBatchKinds = 4;
  struct GBufferPipelines {
    std::array<UniquePipeline, kBatchKinds> materials;
    UniquePipeline sky;
  };
  GBufferPipelines create_gbuffer_pipelines(const Context& context, const shadergen::Registry& shaders,
                                            const RenderTargets& targets, bool with_flags) const;
  void record_gbuffer_with(VkCommandBuffer cmd, const RenderTargets& targets, const GBufferPipelines& pipelines,
                           bool with_flags) const;

  struct MeshBuffers {
    Buffer vertices;
    Buffer indices;
    std::uint32_t index_count = 0;
    VkDescriptorSet base_colour = VK_NULL_HANDLE;  // set 1 of the G-buffer pass and of masked shadows
    std::size_t kind = 0;                          // batch_kind() of the mesh
    bool blend = false;  // Mesh::blend: neither in the G-buffer nor in the shadow map (forward_pass.h)
  };
  // The batches whose mesh is of kind `kind` and that `selection` draws, in scene order. With
  // `textured`, each binds its mesh's base colour texture first (the G-buffer pass, masked
  // shadows).
  void draw_batches(VkCommandBuffer cmd, bool textured, std::size_t kind, const BatchSelection& selection) const;
  void select_drawn_batches(const Scene& scene, const SceneParamsBlock& block, bool cull);
  void create_shadow_pipelines(const Context& context, const shadergen::Registry& shaders,
                               const RenderTargets& targets);

  SceneTextures textures_;
  std::vector<MeshBuffers> meshes_;
  std::vector<MeshBatch> batches_;
  BatchSelection gbuffer_batches_, shadow_batches_;  // per batch of batches_
  Buffer instances_;
  Buffer params_;
  UniqueDescriptorSetLayout set_layout_;
  UniquePipelineLayout layout_;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  std::array<bool, kBatchKinds> kind_drawn_{};      // some batch is of that kind
  GBufferPipelines plain_, flagged_;                // flagged_: only with 2 or more samples
  std::array<UniquePipeline, 2> shadow_pipelines_;  // unmasked (depth only), masked
};

}  // namespace tilelight
