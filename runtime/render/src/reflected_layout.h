#pragma once
// Layouts built from the reflection of several shaders that share one pipeline layout (the
// three passes of a GPU-driven build; classification and the G-buffer dump): the SPIR-V, not
// the C++, says which bindings and how many push-constant bytes exist, so a shader change
// cannot silently disagree with the runtime. shadergen/vulkan.h converts one shader's
// reflection; this merges several and checks what the runtime binds against the result.

#include <shadergen/registry.h>

#include <vulkan/vulkan.h>

#include <cstdint>
#include <initializer_list>
#include <span>
#include <string_view>
#include <vector>

namespace tilelight {

// Set `set` of every source (a registry's pipeline_layout or a shader's reflection.bindings):
// one VkDescriptorSetLayoutBinding per binding number, in binding order, with the stages of
// every source that uses it. Throws tilelight::Error naming `what` when two sources give one
// binding different types or counts.
std::vector<VkDescriptorSetLayoutBinding> merged_set_bindings(
    std::initializer_list<std::span<const shadergen::DescriptorBinding>> sources, std::uint32_t set,
    std::string_view what);

// The same for the bindings of every one of `shaders` (none null).
std::vector<VkDescriptorSetLayoutBinding> merged_set_bindings(std::span<const shadergen::Reflection* const> shaders,
                                                              std::uint32_t set, std::string_view what);

// The push-constant range that `stages` need to run every one of `shaders` (none null): the
// largest block among them from offset 0; empty when none has push constants.
std::vector<VkPushConstantRange> merged_push_constant_ranges(
    std::initializer_list<const shadergen::Reflection*> shaders, VkShaderStageFlags stages);
std::vector<VkPushConstantRange> merged_push_constant_ranges(std::span<const shadergen::Reflection* const> shaders,
                                                             VkShaderStageFlags stages);

// The bytes of that range: 0 when `ranges` is empty.
std::uint32_t push_constant_bytes(std::span<const VkPushConstantRange> ranges);

// Throws tilelight::Error naming `what` and both lists unless `bindings` (one set, in binding
// order) are exactly one descriptor of each of `types`, at bindings 0..types.size()-1: what a
// pass binds that writes those descriptors in order.
void check_bindings(std::span<const VkDescriptorSetLayoutBinding> bindings, std::span<const VkDescriptorType> types,
                    std::string_view what);

// check_bindings() with `count` storage buffers: exactly `count` single
// storage buffers at bindings 0..count-1: what a pass writes that binds `count` buffers in order.
// Precondition: count >= 1.
void check_storage_buffers(std::span<const VkDescriptorSetLayoutBinding> bindings, std::uint32_t count,
                           std::string_view what);

}  // namespace tilelight
