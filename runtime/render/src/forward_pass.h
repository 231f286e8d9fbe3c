#pragma once
// The forward pass for alpha-blended materials (Tabula Rasa §19.3, §19.8.1; docs/local-lights.md,
// "Forward pass for blended materials"): every instance of a blended mesh (Mesh::blend) drawn
// after the deferred passes and the local lights, back to front (forward_selection.h), lit by
// uber/forward.frag (the sun with its shadow map, the instance's K most important local lights,
// fog: the deferred passes' shading library) and blended SRC_ALPHA, ONE_MINUS_SRC_ALPHA into
// the light target. The same draws go into every light target (classified, naive, dynamic), so
// the targets stay equal per pixel.
//
// Depth: the light target is single-sampled and the G-buffer may be multisampled, so each pass
// first writes a single-sampled depth of its own (uber/forward_depth.frag: the nearest of the
// pixel's samples' RT3 depths, as the local lights' resolve takes it), then tests the blended
// geometry LESS against it, without depth writes.
//
// Descriptor sets, from the domain's merged reflection: set 0 the lighting parameters, RT3 and
// the shadow map (lighting_params.glsl's bindings) and the forward block (binding 8,
// forward_params.glsl), set 1 the scene's local lights (one LocalLightBlock each), set 2 the
// mesh's base colour texture (the scene textures' own set), set 3 the local lights' shadow atlas
// and faces (LocalLightShadows, where some light has a map); push constants: the draw's lights.
// An instance whose chosen lights include one with a map is drawn with LOCAL_SHADOWS.

#include "forward_selection.h"
#include "light_target_layout.h"
#include "local_light_passes.h"
#include "local_light_shadows.h"
#include "render_targets.h"
#include "scene_passes.h"
#include "scene_textures.h"
#include "tilelight/scene/scene.h"
#include "tilelight/scene/uniform_blocks.h"
#include "tilelight/vulkan/buffer.h"
#include "tilelight/vulkan/image.h"
#include "tilelight/vulkan/sampler.h"
#include "tilelight/vulkan/vk_handles.h"

#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <vector>

namespace shadergen {
struct Registry;
}

namespace tilelight {

class Context;

class ForwardPass {
 public:
  // Uploads the blended meshes and instances and builds the pipelines they need (nothing when
  // the scene has no blended mesh). `camera` is the one the frame is drawn from (the sort).
  // `scene_passes`: the meshes' buffers and the scene's textures (both outlive this).
  // `shadows`: the local lights' maps (rendered before this pass records, every frame they are).
  ForwardPass(const Context& context, const Scene& scene, const Camera& camera, const RenderTargets& targets,
              const LightingParamsBlock& params, const ScenePasses& scene_passes, VkDescriptorPool pool,
              const LocalLightShadows& shadows);

  // Blended instances drawn per light target (0: the pass records nothing).
  std::size_t instance_count() const { return draws_.size(); }

  // Blends every blended instance into `target`, which the passes before left in
  // TRANSFER_SRC_OPTIMAL and this leaves there. Nothing without blended instances.
  void record(VkCommandBuffer cmd, const RenderTargets& targets, LocalLightTarget target) const;

 private:
  struct MeshBuffers {                             // what a blended mesh's draws bind besides its buffers
    VkDescriptorSet base_colour = VK_NULL_HANDLE;  // set 2
    bool culled = false;                           // single-sided: back faces culled
  };
  void upload(const Context& context, const Scene& scene, const SceneTextures& textures,
              const SceneParamsBlock& scene_params, const LocalLightShadows& shadows);
  void create_sets(const Context& context, const RenderTargets& targets, VkDescriptorPool pool,
                   const SceneTextures& textures, const LocalLightShadows& shadows);
  // The draw's permutation: LOCAL_LIGHTS with lights, LOCAL_SHADOWS where one of them has a map.
  std::uint32_t raw_id_of(const ForwardDraw& draw) const;
  void create_framebuffers(const Context& context, const RenderTargets& targets);
  void create_pipelines(const Context& context);

  const shadergen::Registry* shaders_;
  const ScenePasses* scene_passes_;  // the meshes' vertex and index buffers (ScenePasses::bind_mesh)
  std::vector<ForwardDraw> draws_;   // back to front; draw i reads instance i of instances_
  std::vector<MeshBuffers> meshes_;  // by Scene::meshes index (set for the blended ones)
  LightingParamsBlock params_block_;
  Buffer params_, forward_params_, lights_, instances_;
  Sampler sampler_;
  UniqueRenderPass render_pass_;
  Image depth_;                                    // the single-sampled depth the geometry is tested against
  std::array<UniqueFramebuffer, 3> framebuffers_;  // per LocalLightTarget
  LightTargetLayout layout_;
  VkDescriptorSet set0_ = VK_NULL_HANDLE, set1_ = VK_NULL_HANDLE;
  VkDescriptorSet set3_ = VK_NULL_HANDLE;  // the shadow maps; only where some light has one
  std::vector<bool> light_has_map_;        // per scene light
  UniquePipeline depth_pipeline_;
  // By [raw ID (LOCAL_LIGHTS bit 0, LOCAL_SHADOWS bit 1)][culled]: only those some draw uses.
  std::array<std::array<UniquePipeline, 2>, 4> pipelines_;
};

}  // namespace tilelight
