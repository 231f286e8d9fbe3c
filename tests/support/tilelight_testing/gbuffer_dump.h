#pragma once
// Copies every sample of a renderer's G-buffer into host-visible memory, as stored
// (shaders/gbuffer_dump.comp, from the test domain gbuffer_dump.json): multisampled images
// cannot be copied to the host directly. It binds the renderer's own lighting set 0, so it reads
// exactly what classification and lighting read.

#include "tilelight_testing/gbuffer_samples.h"

#include "tilelight/vulkan/buffer.h"
#include "tilelight/vulkan/vk_handles.h"

#include <vulkan/vulkan.h>

namespace tilelight {

class Context;
class LightingInterface;
class RenderTargets;

class GBufferDump {
 public:
  // `targets` and `lighting`: one renderer's (LightingInterface binds `targets`); both must
  // outlive this object.
  GBufferDump(const Context& context, const RenderTargets& targets, const LightingInterface& lighting);

  // Dispatches the copy and makes the buffer visible to the host.
  void record(VkCommandBuffer cmd) const;
  // What the last submitted record() copied; valid once that submission completed.
  GBufferSamples read() const;

 private:
  const LightingInterface* lighting_;
  std::uint32_t width_, height_, samples_;
  Buffer values_;
  UniqueDescriptorPool pool_;
  UniqueDescriptorSetLayout output_layout_;
  UniquePipelineLayout layout_;
  VkDescriptorSet output_set_ = VK_NULL_HANDLE;
  UniquePipeline pipeline_;
};

}  // namespace tilelight
