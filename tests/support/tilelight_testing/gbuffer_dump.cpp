#include "tilelight_testing/gbuffer_dump.h"

#include "tilelight_testing/gbuffer_form_shader.h"

#include "descriptors.h"
#include "lighting_interface.h"
#include "pipelines.h"
#include "reflected_layout.h"
#include "render_targets.h"
#include "tilelight/vulkan/barriers.h"
#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <gbuffer_dump_shaders.h>

#include <array>

namespace tilelight {
namespace {

constexpr std::uint32_t kOutputSet = 1;  // gbuffer_dump.comp: set 1, binding 0
constexpr std::uint32_t kGroupSize = 8;  // local_size_x and _y

// The dump compiled for this G-buffer's form.
const shadergen::Permutation& dump_shader(VkSampleCountFlagBits samples) {
  return gbuffer_form_shader(gbuffer_dump::registry(),
                             gbuffer_dump::raw_id({.SINGLE_SAMPLED = samples == VK_SAMPLE_COUNT_1_BIT}),
                             "gbuffer_dump");
}

}  // namespace

GBufferDump::GBufferDump(const Context& context, const RenderTargets& targets, const LightingInterface& lighting)
    : lighting_(&lighting),
      width_(targets.extent().width),
      height_(targets.extent().height),
      samples_(static_cast<std::uint32_t>(targets.samples())) {
  const shadergen::Permutation& shader = dump_shader(targets.samples());
  GBufferSamples shape{width_, height_, samples_, {}};
  values_ = Buffer(context, {shape.value_count() * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                             MemoryUse::HostReadback, "G-buffer dump"});

  // Set 0 is the renderer's lighting set; set 1 and the push constants are what the dump's own
  // reflection declares.
  const std::vector<VkDescriptorSetLayoutBinding> output =
      merged_set_bindings({shader.reflection.bindings}, kOutputSet, "G-buffer dump output set");
  check_storage_buffers(output, 1, "G-buffer dump output set");
  output_layout_ = create_descriptor_set_layout(context, output, "G-buffer dump output layout");
  const std::array<VkDescriptorSetLayout, 2> sets{lighting.set0_layout(), output_layout_.get()};
  layout_ = create_pipeline_layout(context, sets,
                                   merged_push_constant_ranges({&shader.reflection}, VK_SHADER_STAGE_COMPUTE_BIT),
                                   "G-buffer dump layout");
  pool_ = create_descriptor_pool(context, 1, "G-buffer dump descriptors");
  output_set_ = allocate_descriptor_set(context, pool_.get(), output_layout_.get(), "G-buffer dump output set");
  write_buffer_descriptor(context, output_set_, 0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, values_.handle());
  pipeline_ = create_compute_pipeline(context, layout_.get(), shader.spirv, {}, "G-buffer dump");
}

void GBufferDump::record(VkCommandBuffer cmd) const {
  const std::array<VkDescriptorSet, 2> sets{lighting_->set0(), output_set_};
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.get());
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_.get(), 0,
                          static_cast<std::uint32_t>(sets.size()), sets.data(), 0, nullptr);
  vkCmdDispatch(cmd, (width_ + kGroupSize - 1) / kGroupSize, (height_ + kGroupSize - 1) / kGroupSize, 1);
  buffer_barrier(cmd, values_.handle(), {VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT},
                 {VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT});
}

GBufferSamples GBufferDump::read() const {
  GBufferSamples out{width_, height_, samples_, {}};
  const std::span<const float> values = values_.as<const float>();
  out.values.assign(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(out.value_count()));
  return out;
}

}  // namespace tilelight
