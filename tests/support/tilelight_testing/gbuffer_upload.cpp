#include "tilelight_testing/gbuffer_upload.h"

#include "tilelight_testing/gbuffer_form_shader.h"

#include "descriptors.h"
#include "pipelines.h"
#include "reflected_layout.h"
#include "render_targets.h"
#include "shader_registry.h"
#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <gbuffer_upload_shaders.h>

#include <array>
#include <string>

namespace tilelight {
namespace {

// The upload compiled for this G-buffer's form.
const shadergen::Permutation& upload_shader(VkSampleCountFlagBits samples) {
  return gbuffer_form_shader(gbuffer_upload::registry(),
                             gbuffer_upload::raw_id({.SINGLE_SAMPLED = samples == VK_SAMPLE_COUNT_1_BIT}),
                             "gbuffer_upload");
}

}  // namespace

GBufferUpload::GBufferUpload(const Context& context, const RenderTargets& targets, const GBufferSamples& samples,
                             const glm::vec4& sun_direction)
    : push_{{targets.extent().width, targets.extent().height, samples.samples, 0}, sun_direction} {
  if (!context.features().sample_rate_shading) {
    throw Error("a synthetic G-buffer needs sample-rate shading, which " + context.device_name() + " lacks");
  }
  if (samples.width != targets.extent().width || samples.height != targets.extent().height ||
      samples.samples != static_cast<std::uint32_t>(targets.samples()) ||
      samples.values.size() != samples.value_count()) {
    throw Error("the synthetic G-buffer does not match the frame's size and sample count");
  }
  const shadergen::Permutation& shader = upload_shader(targets.samples());
  const std::vector<VkPushConstantRange> push =
      merged_push_constant_ranges({&shader.reflection}, VK_SHADER_STAGE_FRAGMENT_BIT);
  if (push_constant_bytes(push) != sizeof(UploadPush)) {
    throw Error("gbuffer_upload.frag pushes " + std::to_string(push_constant_bytes(push)) +
                " bytes; the test support writes " + std::to_string(sizeof(UploadPush)));
  }
  samples_ = Buffer(context, {samples.values.size() * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                              MemoryUse::HostUpload, "synthetic G-buffer samples"});
  samples_.write_values(std::span<const float>(samples.values));

  const std::vector<VkDescriptorSetLayoutBinding> bindings =
      merged_set_bindings({shader.reflection.bindings}, 0, "G-buffer upload set");
  check_storage_buffers(bindings, 1, "G-buffer upload set");
  set_layout_ = create_descriptor_set_layout(context, bindings, "G-buffer upload set layout");
  const std::array<VkDescriptorSetLayout, 1> set_layouts{set_layout_.get()};
  layout_ = create_pipeline_layout(context, set_layouts, push, "G-buffer upload layout");
  pool_ = create_descriptor_pool(context, 1, "G-buffer upload descriptors");
  set_ = allocate_descriptor_set(context, pool_.get(), set_layout_.get(), "G-buffer upload set");
  write_buffer_descriptor(context, set_, 0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, samples_.handle());

  GraphicsPipelineDesc desc = targets.gbuffer_pipeline_desc(layout_.get(), "G-buffer upload");
  desc.vertex_spirv = light_companions(targets.samples()).sky_vertex.shader.spirv;  // a full-screen triangle
  desc.fragment_spirv = shader.spirv;
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
