#pragma once
// The scene passes: the sun shadow map (depth only) and the G-buffer (materials, then sky).
// Meshes and instances are uploaded once; the camera is fixed per renderer.

#include "render_targets.h"
#include "tilelight/scene/scene.h"
#include "tilelight/vulkan/buffer.h"
#include "tilelight/vulkan/vk_handles.h"

#include <vector>

namespace tilelight {

class Context;

class ScenePasses {
 public:
  ScenePasses(const Context& context, const Scene& scene, const Camera& camera, const RenderTargets& targets,
              VkDescriptorPool pool);

  // Shadow map pass, then the G-buffer pass (geometry, then sky at the far plane).
  void record_shadow_map(VkCommandBuffer cmd, const RenderTargets& targets) const;
  void record_gbuffer(VkCommandBuffer cmd, const RenderTargets& targets) const;

 private:
  struct MeshBuffers {
    Buffer vertices;
    Buffer indices;
    std::uint32_t index_count = 0;
  };
  void draw_batches(VkCommandBuffer cmd) const;

  std::vector<MeshBuffers> meshes_;
  std::vector<MeshBatch> batches_;
  Buffer instances_;
  Buffer params_;
  UniqueDescriptorSetLayout set_layout_;
  UniquePipelineLayout layout_;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  UniquePipeline gbuffer_pipeline_, sky_pipeline_, shadow_pipeline_;
};

}  // namespace tilelight
