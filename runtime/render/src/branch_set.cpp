#include "branch_set.h"

#include "descriptors.h"
#include "pipelines.h"
#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <shadergen/vulkan.h>

#include <algorithm>
#include <string>

namespace tilelight {
namespace {

// The block's one binding, from the reflection of the build's blobs, made dynamic.
VkDescriptorSetLayoutBinding branch_binding(const shadergen::Registry& registry, const shadergen::BranchBlock& block) {
  std::vector<VkDescriptorSetLayoutBinding> bindings =
      shadergen::vk::descriptor_set_layout_bindings(registry.pipeline_layout, block.set);
  if (bindings.size() != 1 || bindings[0].binding != block.binding ||
      bindings[0].descriptorType != VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER || bindings[0].descriptorCount != 1) {
    throw Error(std::string(registry.name) + ": set " + std::to_string(block.set) +
                " must hold the branch block alone, one uniform buffer at binding " + std::to_string(block.binding) +
                " (the reflection has " + std::to_string(bindings.size()) + " bindings there)");
  }
  bindings[0].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC;
  return bindings[0];
}

VkDeviceSize round_up(VkDeviceSize value, VkDeviceSize alignment) {
  return alignment <= 1 ? value : (value + alignment - 1) / alignment * alignment;
}

}  // namespace

BranchSet::BranchSet(const Context& context, const LightClasses& classes, VkDescriptorPool pool) {
  const shadergen::BranchBlock& block = classes.shaders.branch_block;
  if (block.size == 0) return;  // no branch feature: inactive
  if (block.set == 0) throw Error("the branch block may not be in set 0: the light pass's lighting set is there");
  set_number_ = block.set;
  const VkDescriptorSetLayoutBinding binding = branch_binding(*classes.shaders.registry, block);
  stride_ = round_up(block.size, std::max<VkDeviceSize>(context.limits().min_uniform_buffer_offset_alignment, 1));

  values_ = Buffer(context, {stride_ * std::max<std::size_t>(classes.classes.size(), 1),
                             VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, MemoryUse::HostUpload, "branch values per class"});
  for (std::size_t c = 0; c < classes.classes.size(); ++c) {
    const shadergen::BranchValues& v = classes.classes[c].branch;
    if (v.size != block.size) throw Error("a draw class's branch values are not the block's size");
    values_.write_values(std::span<const std::uint32_t>(v.words.data(), v.size / sizeof(std::uint32_t)), c * stride_);
  }
  layout_ = create_descriptor_set_layout(context, std::span(&binding, 1), "branch block set layout");
  empty_layout_ = create_descriptor_set_layout(context, {}, "empty set layout (below the branch set)");
  set_ = allocate_descriptor_set(context, pool, layout_.get(), "branch block set");
  write_buffer_descriptor(context, set_, block.binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, values_.handle(),
                          block.size);
}

UniquePipelineLayout BranchSet::pipeline_layout(const Context& context, std::span<const VkDescriptorSetLayout> sets,
                                                std::span<const VkPushConstantRange> push,
                                                std::string_view name) const {
  if (sets.size() > set_number_) {
    throw Error(std::string(name) + ": the branch block's set " + std::to_string(set_number_) +
                " is one the light pass already uses");
  }
  std::vector<VkDescriptorSetLayout> all(sets.begin(), sets.end());
  all.resize(set_number_, empty_layout_.get());
  all.push_back(layout_.get());
  return create_pipeline_layout(context, all, push, name);
}

void BranchSet::bind(VkCommandBuffer cmd, VkPipelineBindPoint point, VkPipelineLayout layout,
                     std::uint32_t draw_class) const {
  const auto offset = static_cast<std::uint32_t>(draw_class * stride_);
  vkCmdBindDescriptorSets(cmd, point, layout, set_number_, 1, &set_, 1, &offset);
}

}  // namespace tilelight
