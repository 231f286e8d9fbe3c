#include "gbuffer_upload.h"

#include "descriptors.h"
#include "pipelines.h"
#include "shader_registry.h"
#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <split_second_shaders.h>

#include <array>

namespace tilelight {

GBufferUpload::GBufferUpload(const Context& context, const RenderTargets& targets, const GBufferSamples& samples,
                             const glm::vec4& sun_direction, VkDescriptorPool pool)
    : push_{{targets.extent().width, targets.extent().height, samples.samples, 0}, sun_direction} {
  if (!context.features().sample_rate_shading) {
    throw Error("a synthetic G-buffer needs sample-rate shading, which " + context.device_name() + " lacks");
  }
  if (samples.width != targets.extent().width || samples.height != targets.extent().height ||
      samples.samples != static_cast<std::uint32_t>(targets.samples()) ||
      samples.values.size() != samples.value_count()) {
    throw Error("the synthetic G-buffer does not match the frame's size and sample count");
  }
  samples_ = Buffer(context, {samples.values.size() * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                              MemoryUse::HostUpload, "synthetic G-buffer samples"});
  samples_.write_values(std::span<const float>(samples.values));

  const VkDescriptorSetLayoutBinding binding{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT,
                                             nullptr};
  set_layout_ = create_descriptor_set_layout(context, std::span(&binding, 1), "G-buffer upload set layout");
  const VkDescriptorSetLayout set_layouts[] = {set_layout_.get()};
  const VkPushConstantRange push{VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(UploadPush)};
  layout_ = create_pipeline_layout(context, set_layouts, std::span(&push, 1), "G-buffer upload layout");
  set_ = allocate_descriptor_set(context, pool, set_layout_.get(), "G-buffer upload set");
  write_buffer_descriptor(context, set_, 0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, samples_.handle());

  GraphicsPipelineDesc desc = targets.gbuffer_pipeline_desc(layout_.get(), "G-buffer upload");
  const shadergen::Registry& shaders = shaders_for(targets.samples());
  desc.vertex_spirv = companion_spirv(shaders, "sky_vertex");  // a full-screen triangle
  desc.fragment_spirv = companion_spirv(shaders, "gbuffer_upload");
  desc.depth_test = false;  // no shader reads the depth target; the surface depth is RT3
  pipeline_ = create_graphics_pipeline(context, desc);
}

void GBufferUpload::record(VkCommandBuffer cmd, const RenderTargets& targets) const {
  targets.begin_gbuffer_pass(cmd);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.get());
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_.get(), 0, 1, &set_, 0, nullptr);
  vkCmdPushConstants(cmd, layout_.get(), VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(push_), &push_);
  vkCmdDraw(cmd, 3, 1, 0, 0);
  vkCmdEndRenderPass(cmd);
}

}  // namespace tilelight
