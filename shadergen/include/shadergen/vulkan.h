// shadergen/vulkan.h - what a Vulkan renderer does with a generated registry's permutations,
// ready to hand to Vulkan: shader-module create-infos, the descriptor-set layout bindings of
// each set, the push-constant ranges and the specialization map entries.
//
// Only a consumer that includes this header needs the Vulkan headers (the registry header
// stays standard-library only). Nothing here calls Vulkan, so nothing links against it. The
// returned structures point into the registry's constant data (words, never copied), which
// lives as long as the program.
#pragma once

#include <vulkan/vulkan.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "shadergen/registry.h"

namespace shadergen::vk {

// A create-info for `words` (a permutation's `spirv` or `vertex_spirv`); pNext and flags zero.
// Precondition: `words` is not empty (a pruned permutation has no SPIR-V).
inline VkShaderModuleCreateInfo shader_module_create_info(std::span<const std::uint32_t> words) {
  VkShaderModuleCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
  info.codeSize = words.size() * sizeof(std::uint32_t);
  info.pCode = words.data();
  return info;
}

// The create-info of a permutation's (fragment or only) shader.
inline VkShaderModuleCreateInfo shader_module_create_info(const Permutation& permutation) {
  return shader_module_create_info(permutation.spirv);
}

// How many descriptor sets `bindings` use: the highest set number plus one (0 without any).
inline std::uint32_t descriptor_set_count(std::span<const DescriptorBinding> bindings) {
  std::uint32_t count = 0;
  for (const DescriptorBinding& b : bindings) count = std::max(count, b.set + 1);
  return count;
}

// The VkDescriptorSetLayoutBindings of set `set`, in binding order, one per binding (aliases
// are merged by reflection). `bindings` is a registry's `pipeline_layout` or, with
// "layout": "per_permutation", a permutation's `reflection.bindings`. A runtime-sized array
// (`texture2D t[]`) gets `runtime_count` descriptors: the renderer chooses it, and the layout
// then also needs VK_DESCRIPTOR_BINDING_VARIABLE_DESCRIPTOR_COUNT_BIT. No immutable samplers.
inline std::vector<VkDescriptorSetLayoutBinding> descriptor_set_layout_bindings(
    std::span<const DescriptorBinding> bindings, std::uint32_t set, std::uint32_t runtime_count = 0) {
  std::vector<VkDescriptorSetLayoutBinding> out;
  for (const DescriptorBinding& b : bindings) {
    if (b.set != set) continue;
    VkDescriptorSetLayoutBinding binding{};
    binding.binding = b.binding;
    binding.descriptorType = static_cast<VkDescriptorType>(b.kind);
    binding.descriptorCount = b.runtime_sized ? runtime_count : b.count;
    binding.stageFlags = static_cast<VkShaderStageFlags>(b.stages);
    out.push_back(binding);
  }
  std::sort(out.begin(), out.end(), [](const VkDescriptorSetLayoutBinding& a, const VkDescriptorSetLayoutBinding& b) {
    return a.binding < b.binding;
  });
  return out;
}

// The push-constant ranges of a registry's shared layout (empty with "per_permutation").
inline std::vector<VkPushConstantRange> push_constant_ranges(const Registry& registry) {
  std::vector<VkPushConstantRange> out;
  for (const PushConstantRange& p : registry.push_constants)
    out.push_back({static_cast<VkShaderStageFlags>(p.stages), 0, p.size});
  return out;
}

// The push-constant range of one blob used by `stages` (a per-permutation layout); empty when
// it has no push constants.
inline std::vector<VkPushConstantRange> push_constant_ranges(const Reflection& reflection, VkShaderStageFlags stages) {
  if (reflection.push_constant_size == 0) return {};
  return {{stages, 0, reflection.push_constant_size}};
}

// One VkSpecializationMapEntry per specialization constant of a blob, in constant_id order:
// entry i reads 4 bytes (a VkBool32 for a bool) at offset 4 * i of the data.
inline std::vector<VkSpecializationMapEntry> specialization_map_entries(const Reflection& reflection) {
  std::vector<VkSpecializationMapEntry> out;
  for (const SpecializationConstant& c : reflection.specialization_constants)
    out.push_back({c.id, static_cast<std::uint32_t>(out.size() * sizeof(std::uint32_t)), sizeof(std::uint32_t)});
  return out;
}

// The data those entries read, holding every constant's default: overwrite the ones to change.
inline std::vector<std::uint32_t> specialization_defaults(const Reflection& reflection) {
  std::vector<std::uint32_t> out;
  for (const SpecializationConstant& c : reflection.specialization_constants) out.push_back(c.default_bits);
  return out;
}

// The VkSpecializationInfo of a raw ID's specialization data (generated N::specialization()). It
// points into `specialization`, which must outlive the pipeline's creation. With no
// specialization feature it is empty (mapEntryCount 0), which Vulkan accepts as no data.
inline VkSpecializationInfo specialization_info(const Specialization& specialization) {
  // Layout-compatible, so the registry's constant map is handed to Vulkan as it is.
  static_assert(sizeof(SpecializationMapEntry) == sizeof(VkSpecializationMapEntry) &&
                offsetof(SpecializationMapEntry, offset) == offsetof(VkSpecializationMapEntry, offset) &&
                offsetof(SpecializationMapEntry, size) == offsetof(VkSpecializationMapEntry, size));
  VkSpecializationInfo info{};
  info.mapEntryCount = static_cast<std::uint32_t>(specialization.map.size());
  info.pMapEntries = reinterpret_cast<const VkSpecializationMapEntry*>(specialization.map.data());
  info.dataSize = specialization.data_size;
  info.pData = specialization.data.data();
  return info;
}

}  // namespace shadergen::vk

namespace shadergen {
// The name the issue tracker and docs/adopting.md use: shadergen::vulkan::specialization_info().
namespace vulkan = vk;
}  // namespace shadergen
