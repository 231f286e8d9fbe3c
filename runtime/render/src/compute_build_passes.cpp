#include "compute_build_passes.h"

#include "descriptors.h"
#include "reflected_layout.h"
#include "tilelight/vulkan/error.h"

#include <fmt/format.h>
#include <shadergen/vulkan.h>

namespace tilelight {
namespace {

constexpr std::uint32_t kBuffers = 5;  // tile IDs, LUT, counters, two outputs

std::array<std::uint32_t, 256> class_lut(std::span<const std::uint8_t> class_for_raw, std::span<const bool> pruned) {
  constexpr std::uint32_t kNoClass = 0xFF;  // the shaders' NO_CLASS
  std::array<std::uint32_t, 256> lut{};
  lut.fill(kNoClass);
  for (std::size_t raw = 0; raw < class_for_raw.size(); ++raw) {
    if (!pruned[raw]) lut[raw] = class_for_raw[raw];
  }
  return lut;
}

// A pass that used another set would need a layout the build does not make.
void check_set_zero_only(const ComputeBuildPass& pass, const std::string& name) {
  if (shadergen::vk::descriptor_set_count(pass.shader->reflection.bindings) > 1) {
    throw Error(name + ": a pass's shader uses a descriptor set other than 0");
  }
}

}  // namespace

std::uint32_t workgroups(std::uint32_t invocations, const shadergen::Permutation& pass) {
  const std::uint32_t group = pass.reflection.local_size[0];
  return (invocations + group - 1) / group;
}

ComputeBuild::ComputeBuild(const Context& context, VkDescriptorPool pool, const ComputeBuildInput& input,
                           ComputeBuildDesc desc)
    : push_(std::move(desc.push)), groups_(desc.groups), counter_bytes_(desc.counter_bytes), consumer_(desc.consumer) {
  create_buffers(context, input, desc.name);
  create_layout(context, desc);
  set_ = allocate_descriptor_set(context, pool, set_layout_.get(), desc.name + " set");
  const std::array<VkBuffer, kBuffers> buffers{input.tile_ids, lut_.handle(), counters_.handle(), desc.outputs[0],
                                               desc.outputs[1]};
  for (std::uint32_t i = 0; i < kBuffers; ++i) {
    write_buffer_descriptor(context, set_, i, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, buffers[i]);
  }
  count_ = create_compute_pipeline(context, layout_.get(), desc.count.shader->spirv, desc.count.constants,
                                   desc.name + ": count");
  prefix_ = create_compute_pipeline(context, layout_.get(), desc.prefix.shader->spirv, desc.prefix.constants,
                                    desc.name + ": prefix sum");
  fill_ = create_compute_pipeline(context, layout_.get(), desc.fill.shader->spirv, desc.fill.constants,
                                  desc.name + ": fill");
}

void ComputeBuild::create_buffers(const Context& context, const ComputeBuildInput& input, const std::string& name) {
  const std::array<std::uint32_t, 256> lut = class_lut(input.class_for_raw, input.pruned);
  lut_ = Buffer(context, {sizeof(lut), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::HostUpload, name + " LUT"});
  lut_.write_values(std::span<const std::uint32_t>(lut));
  counters_ = Buffer(context, {counter_bytes_,
                               VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                                   VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                               MemoryUse::DeviceLocal, name + " counters"});
  host_counters_ = Buffer(context, {counter_bytes_, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::HostReadback,
                                    name + " counters (host copy)"});
}

void ComputeBuild::create_layout(const Context& context, const ComputeBuildDesc& desc) {
  for (const ComputeBuildPass* pass : {&desc.count, &desc.prefix, &desc.fill}) check_set_zero_only(*pass, desc.name);
  const shadergen::Reflection& count = desc.count.shader->reflection;
  const shadergen::Reflection& prefix = desc.prefix.shader->reflection;
  const shadergen::Reflection& fill = desc.fill.shader->reflection;
  // No one pass need read every buffer (the prefix sum reads two): the set is their union.
  const std::vector<VkDescriptorSetLayoutBinding> bindings =
      merged_set_bindings({count.bindings, prefix.bindings, fill.bindings}, 0, desc.name);
  check_storage_buffers(bindings, kBuffers, desc.name);
  const std::vector<VkPushConstantRange> push =
      merged_push_constant_ranges({&count, &prefix, &fill}, VK_SHADER_STAGE_COMPUTE_BIT);
  const std::size_t push_bytes = push_.size() * sizeof(std::uint32_t);
  if (push_constant_bytes(push) != push_bytes) {
    throw Error(fmt::format("{}: the shaders take {} bytes of push constants; the runtime pushes {}", desc.name,
                            push_constant_bytes(push), push_bytes));
  }
  set_layout_ = create_descriptor_set_layout(context, bindings, desc.name + " set layout");
  const VkDescriptorSetLayout set_layouts[] = {set_layout_.get()};
  layout_ = create_pipeline_layout(context, set_layouts, push, desc.name + " layout");
}

void ComputeBuild::record(VkCommandBuffer cmd) const {
  const Scope compute_rw{VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT};
  vkCmdFillBuffer(cmd, counters_.handle(), 0, VK_WHOLE_SIZE, 0);
  buffer_barrier(cmd, counters_.handle(), {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT}, compute_rw);

  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_.get(), 0, 1, &set_, 0, nullptr);
  if (!push_.empty()) {
    vkCmdPushConstants(cmd, layout_.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0,
                       static_cast<std::uint32_t>(push_.size() * sizeof(std::uint32_t)), push_.data());
  }
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, count_.get());
  vkCmdDispatch(cmd, groups_, 1, 1);
  memory_barrier(cmd, compute_rw, compute_rw);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, prefix_.get());
  vkCmdDispatch(cmd, 1, 1, 1);
  memory_barrier(cmd, compute_rw, compute_rw);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, fill_.get());
  vkCmdDispatch(cmd, groups_, 1, 1);

  memory_barrier(cmd, compute_rw,
                 {consumer_.stages | VK_PIPELINE_STAGE_TRANSFER_BIT, consumer_.access | VK_ACCESS_TRANSFER_READ_BIT});
  const VkBufferCopy copy{0, 0, counter_bytes_};
  vkCmdCopyBuffer(cmd, counters_.handle(), host_counters_.handle(), 1, &copy);
  buffer_barrier(cmd, host_counters_.handle(), {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT},
                 {VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT});
}

}  // namespace tilelight
