#pragma once
// Replaces the scene's G-buffer pass with given sample values (tests: synthetic tiles that
// reach classes the scene does not produce). Same render pass and targets as the scene pass;
// the shader is the test domain gbuffer_upload.json's (shaders/gbuffer_upload.frag).

#include "tilelight_testing/gbuffer_samples.h"

#include "tilelight/vulkan/buffer.h"
#include "tilelight/vulkan/vk_handles.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>

namespace tilelight {

class Context;
class RenderTargets;

class GBufferUpload {
 public:
  // Precondition: `samples` matches the targets' size and sample count, and the device offers
  // sample-rate shading (checked: tilelight::Error otherwise). `sun_direction` (xyz, towards the
  // sun) decides the sun-facing bits, as the material shaders do with the scene's.
  GBufferUpload(const Context& context, const RenderTargets& targets, const GBufferSamples& samples,
                const glm::vec4& sun_direction);
  void record(VkCommandBuffer cmd, const RenderTargets& targets) const;

 private:
  // gbuffer_upload.frag's push constants (their size is checked against its reflection).
  struct UploadPush {
    std::array<std::uint32_t, 4> size;  // width, height, samples, 0
    glm::vec4 sun_direction;
  };

  UploadPush push_;
  Buffer samples_;
  UniqueDescriptorPool pool_;
  UniqueDescriptorSetLayout set_layout_;
  UniquePipelineLayout layout_;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  UniquePipeline pipeline_;
};

}  // namespace tilelight
