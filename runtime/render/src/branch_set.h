#pragma once
// The branch features' uniform block (shadergen's "branch_block", docs/spec-format.md "Kinds")
// as the tile pass binds it: one descriptor set with one dynamic uniform buffer, and one copy
// of the block per draw class in a host-written buffer, at a stride of the device's uniform
// offset alignment. Each class's draw or dispatch binds the set at its own dynamic offset, so a
// class's pipeline (shared by every class of its optimised ID) reads that class's values.
//
// The set number and binding come from the generated N::kBranchBlock and the set's layout from
// the registry's reflection (a uniform buffer there, made dynamic here), so the spec alone says
// where the block lives; it must not be a set the light pass already uses (0; 1 in compute).
// A build without branch features has an inactive BranchSet: nothing is created or bound.

#include "light_classes.h"
#include "tilelight/vulkan/buffer.h"
#include "tilelight/vulkan/vk_handles.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <vector>

namespace tilelight {

class Context;

class BranchSet {
 public:
  // `classes`: the tile pass's classes, with their branch values and the build they come from.
  // Throws tilelight::Error when the registry's reflection does not declare exactly the block
  // at kBranchBlock's set and binding.
  BranchSet(const Context& context, const LightClasses& classes, VkDescriptorPool pool);

  bool active() const { return stride_ != 0; }
  std::uint32_t set_number() const { return set_number_; }

  // The tile pass's pipeline layout: `sets` (the light pass's own, from set 0), then empty
  // layouts up to the branch set, then the branch set's. Precondition: active().
  UniquePipelineLayout pipeline_layout(const Context& context, std::span<const VkDescriptorSetLayout> sets,
                                       std::span<const VkPushConstantRange> push, std::string_view name) const;

  // Binds the set at `draw_class`'s values. Precondition: active(), and `layout` made by
  // pipeline_layout().
  void bind(VkCommandBuffer cmd, VkPipelineBindPoint point, VkPipelineLayout layout, std::uint32_t draw_class) const;

 private:
  std::uint32_t set_number_ = 0;
  VkDeviceSize stride_ = 0;  // 0: inactive
  Buffer values_;
  UniqueDescriptorSetLayout layout_, empty_layout_;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
};

}  // namespace tilelight
