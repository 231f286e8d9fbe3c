#pragma once
// Replaces the scene's G-buffer pass with given sample values (tests: synthetic tiles that
// reach classes the scene does not produce). Same render pass and targets as the scene pass.

#include "render_targets.h"
#include "tilelight/render/tile_renderer.h"
#include "tilelight/vulkan/buffer.h"
#include "tilelight/vulkan/vk_handles.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>

namespace tilelight {

class Context;

class GBufferUpload {
 public:
  // Precondition: `samples` matches the targets' size and sample count, and the device offers
  // sample-rate shading (checked: tilelight::Error otherwise). `sun_direction` (xyz, towards the
  // sun) decides the sun-facing bits, as the material shaders do with the scene's.
  GBufferUpload(const Context& context, const RenderTargets& targets, const GBufferSamples& samples,
                const glm::vec4& sun_direction, VkDescriptorPool pool);
  void record(VkCommandBuffer cmd, const RenderTargets& targets) const;

 private:
  // gbuffer_upload.frag's push constants.
  struct UploadPush {
    std::array<std::uint32_t, 4> size;  // width, height, samples, 0
    glm::vec4 sun_direction;
  };

  UploadPush push_;
  Buffer samples_;
  UniqueDescriptorSetLayout set_layout_;
  UniquePipelineLayout layout_;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  UniquePipeline pipeline_;
};

}  // namespace tilelight
