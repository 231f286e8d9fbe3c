#pragma once
// The local-light passes (Tabula Rasa §19.7, docs/local-lights.md): each of the scene's local
// lights added into a light target after the global pass, blended ONE + ONE, by its own
// permutation of permutations/local_lights.json, reading the G-buffer as the global pass does.
// The full-screen form draws one triangle over the whole frame per light: the chapter's baseline
// and the per-pixel reference. The volume form (§19.7.1, the default) draws each light's volume
// mesh (local_light_volumes.h) with its front faces culled and the "greater or equal" depth test
// against a single-sampled depth and stencil resolved from the G-buffer (the nearest sample's
// depth; the stencil the G-buffer's materials marked, §19.7.2), rejecting stencil 0 (sky).
// Volumes beyond the far plane: depth clamping where the device has depthClamp, else such a
// light is drawn without the depth test (stencil only). The same lights go into every light
// target (classified, naive, dynamic) from bit-identical G-buffers, so the targets stay equal
// per pixel.
//
// Descriptor sets, from the domain's merged reflection: set 0 the G-buffer and the lighting
// parameters (lighting_params.glsl's bindings, a set of its own: the layout is this domain's),
// set 1 the lights (one LocalLightBlock each), set 2 a globe map (the scene texture's set,
// SceneTextures), set 3 the shadow atlas and its faces (LocalLightShadows; bound where some
// light has a map, whose SHADOWED permutation reads it), and push constants: the camera's
// transform and the light's index.

#include "light_target_layout.h"
#include "local_light_shadows.h"
#include "local_light_volumes.h"
#include "render_targets.h"
#include "scene_textures.h"
#include "tilelight/render/tile_renderer.h"
#include "tilelight/scene/scene.h"
#include "tilelight/scene/uniform_blocks.h"
#include "tilelight/vulkan/buffer.h"
#include "tilelight/vulkan/sampler.h"
#include "tilelight/vulkan/vk_handles.h"

#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <map>
#include <vector>

namespace shadergen {
struct Registry;
}

namespace tilelight {

class Context;

// The light targets local lights are added into: the classified path's and the baselines'.
enum class LocalLightTarget { classified, naive, dynamic };

class LocalLightPasses {
 public:
  // Builds a pipeline for each permutation the scene's local lights need (none without lights).
  // Throws tilelight::Error for a globe map that is not one of the scene's textures. `shadows`
  // says which lights have maps (it outlives this).
  LocalLightPasses(const Context& context, const Scene& scene, const RenderTargets& targets,
                   const LightingParamsBlock& params, const SceneTextures& textures, VkDescriptorPool pool,
                   LocalLightPass pass, const LocalLightShadows& shadows);

  std::size_t light_count() const { return draws_.size(); }
  std::uint32_t pipeline_count() const;

  // Adds every light into `target`, which the global pass left in TRANSFER_SRC_OPTIMAL and this
  // leaves there. `tagged_gbuffer`: the G-buffer holds coverage flags (the classified one).
  // Nothing without lights.
  void record(VkCommandBuffer cmd, const RenderTargets& targets, LocalLightTarget target, bool tagged_gbuffer) const;

 private:
  struct Draw {
    std::uint32_t light = 0;
    std::uint32_t raw_id = 0;
    VkDescriptorSet globe = VK_NULL_HANDLE;  // set 2, GLOBE permutations only
    LightVolume volume = LightVolume::sphere;
    bool depth_tested = true;  // false: the volume may cross the far plane and nothing clamps it
  };
  struct PipelinePair {
    UniquePipeline plain, tagged;  // TAGGED_GBUFFER off and on (on only with coverage flags)
  };
  void create_sets(const Context& context, const RenderTargets& targets, VkDescriptorPool pool,
                   const SceneTextures& textures, const std::vector<LocalLight>& lights,
                   const LocalLightShadows& shadows);
  void create_full_screen_pipelines(const Context& context, const RenderTargets& targets);
  void create_volume_pipelines(const Context& context, const RenderTargets& targets, bool depth_clamp);
  void create_volume_meshes(const Context& context);
  void record_full_screen(VkCommandBuffer cmd, const RenderTargets& targets, LocalLightTarget target,
                          bool tagged_gbuffer) const;
  void record_volumes(VkCommandBuffer cmd, const RenderTargets& targets, LocalLightTarget target,
                      bool tagged_gbuffer) const;
  void push_draw(VkCommandBuffer cmd, const Draw& draw) const;
  void create_framebuffers(const Context& context, const RenderTargets& targets);
  void bind(VkCommandBuffer cmd, const RenderTargets& targets, LocalLightTarget target) const;

  const shadergen::Registry* shaders_;
  std::vector<Draw> draws_;
  LightingParamsBlock params_block_;
  Buffer params_, lights_;
  Sampler sampler_;
  LocalLightPass pass_;
  glm::mat4 view_proj_{1.0f};     // the camera's world -> clip (the volumes' vertex shader)
  UniqueRenderPass render_pass_;  // the light target alone (full screen), or + resolved depth-stencil (volumes)
  Image resolved_depth_;          // volumes: the single-sampled depth and stencil they are tested against
  Buffer volume_vertices_, volume_indices_;
  VolumeMeshes meshes_;  // the unit meshes' ranges (the vertices are in the buffers)
  // Per LocalLightTarget: the framebuffers of this pass (the global pass's own are of a
  // render pass that clears).
  std::array<UniqueFramebuffer, 3> framebuffers_;
  LightTargetLayout layout_;
  VkDescriptorSet set0_ = VK_NULL_HANDLE, set1_ = VK_NULL_HANDLE;
  VkDescriptorSet set3_ = VK_NULL_HANDLE;              // the shadow atlas and faces; none without maps
  std::map<std::uint32_t, PipelinePair> full_screen_;  // by raw ID
  UniquePipeline resolve_;                             // volumes: depth and stencil from the G-buffer
  // Volumes, by raw ID * 2 + depth_tested: the pipelines of the permutation.
  std::map<std::uint32_t, PipelinePair> volume_;
};

}  // namespace tilelight
