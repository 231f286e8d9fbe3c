#pragma once
// The local lights' shadow maps (docs/local-lights.md, "Shadows"; issue 38 item 3): one depth
// atlas holding every face of every shadowed light (local_shadow_transforms.h decides which
// lights get faces under the pool's cap, where each face lies and its snapped transform), the
// faces' blocks the local-light shader reads (set 3 of its layout, bound by LocalLightPasses),
// and the pass that renders the scene's meshes into each face (masked meshes discard as in the
// sun's shadow map; batches outside a face's frustum are skipped).
//
// Static maps: the scene does not move, so the faces are rendered in the first frame and kept;
// with `cache` off they are rendered again every frame (the figure to compare).

#include "local_light_block.h"
#include "local_shadow_transforms.h"
#include "tilelight/scene/scene.h"
#include "tilelight/vulkan/buffer.h"
#include "tilelight/vulkan/image.h"
#include "tilelight/vulkan/vk_handles.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string_view>
#include <vector>

namespace shadergen {
struct Registry;
}

namespace tilelight {

class Context;
class ScenePasses;

struct LocalShadowOptions {
  bool enabled = true;
  bool cache = true;
  std::uint32_t face_size = 512;
  std::uint64_t cap_bytes = 256ull << 20;
};

class LocalLightShadows {
 public:
  // Plans the pool and, where some light gets a map, creates the atlas, the faces' buffer and
  // the caster pipelines. `texture_set_layout`: the scene textures' set (masked casters' set 1).
  // Throws tilelight::Error for a face size the device cannot render.
  LocalLightShadows(const Context& context, const Scene& scene, const ScenePasses& scene_passes,
                    VkDescriptorSetLayout texture_set_layout, const LocalShadowOptions& options);

  const LocalShadowPlan& plan() const { return plan_; }
  bool has_maps() const { return plan_.faces != 0; }
  // Preconditions: has_maps(). The atlas (sampled in SHADER_READ_ONLY_OPTIMAL after the first
  // record()) and the faces' blocks (one LocalShadowFaceBlock per face).
  VkImageView atlas_view() const { return atlas_.view(); }
  VkBuffer faces_buffer() const { return faces_.handle(); }
  // Where each light's faces are, in the blocks the shaders read (local_shadow_bindings.glsl):
  // kind.z its first face, kind.w its face count (0 without a map). `blocks`: one per light of
  // the scene, in its order (make_local_light_blocks()).
  void place_faces_in(std::vector<LocalLightBlock>& blocks) const;
  // The set number of the maps in the passes that read them (local_shadow_bindings.glsl).
  static constexpr std::uint32_t kSet = 3;
  // Set kSet of `registry`'s merged layout, checked to be what allocate_set() writes: a sampled
  // image at binding 0, a storage buffer at 1. Throws tilelight::Error naming `pass` otherwise.
  static std::vector<VkDescriptorSetLayoutBinding> set_bindings(const shadergen::Registry& registry,
                                                                std::string_view pass);
  // A descriptor set of `layout`, set 3 of a pass that reads the maps (the atlas at binding 0,
  // read through `sampler` with texelFetch; the faces at binding 1). Preconditions: has_maps().
  VkDescriptorSet allocate_set(const Context& context, VkDescriptorPool pool, VkDescriptorSetLayout layout,
                               VkSampler sampler, std::string_view name) const;

  // Whether this frame renders the maps: the first frame, and every frame without the cache.
  bool renders_this_frame() const { return has_maps() && (!options_.cache || !rendered_); }
  // Renders every face (nothing when !renders_this_frame()). Call once per frame, before any
  // pass that samples the atlas, in the same queue.
  void record(VkCommandBuffer cmd);

 private:
  void create_pipelines(const Context& context, VkDescriptorSetLayout texture_set_layout);
  void create_render_pass(const Context& context);

  LocalShadowOptions options_;
  const ScenePasses* scene_passes_;
  LocalShadowPlan plan_;
  std::vector<LocalShadowFaceBlock> faces_blocks_;
  std::vector<std::vector<bool>> face_batches_;  // per face: the batches inside its frustum
  bool masked_ = false, unmasked_ = false;       // which kinds of casters the scene has
  bool rendered_ = false;
  Image atlas_;
  Buffer faces_;
  UniqueRenderPass render_pass_;
  UniqueFramebuffer framebuffer_;
  UniqueDescriptorSetLayout empty_set_layout_;
  UniquePipelineLayout layout_;
  UniquePipeline opaque_, masked_pipeline_;
};

}  // namespace tilelight
