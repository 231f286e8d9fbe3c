#include "reflected_layout.h"

#include "tilelight/vulkan/error.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <shadergen/vulkan.h>

#include <algorithm>
#include <string>

namespace tilelight {
namespace {

// As GLSL declares them, for messages.
std::string type_name(VkDescriptorType type) {
  switch (type) {
    case VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER: return "uniform buffer";
    case VK_DESCRIPTOR_TYPE_STORAGE_BUFFER: return "storage buffer";
    case VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER: return "combined image sampler";
    case VK_DESCRIPTOR_TYPE_STORAGE_IMAGE: return "storage image";
    default: return fmt::format("descriptor type {}", static_cast<int>(type));
  }
}

// Adds `b` to `merged`, or widens the stages of the binding of its number already there.
void merge_binding(std::vector<VkDescriptorSetLayoutBinding>& merged, const VkDescriptorSetLayoutBinding& b,
                   std::uint32_t set, std::string_view what) {
  const auto same_number = [&](const VkDescriptorSetLayoutBinding& have) { return have.binding == b.binding; };
  const auto have = std::find_if(merged.begin(), merged.end(), same_number);
  if (have == merged.end()) {
    merged.push_back(b);
    return;
  }
  if (have->descriptorType != b.descriptorType || have->descriptorCount != b.descriptorCount) {
    throw Error(fmt::format("{}: the shaders disagree on set {} binding {} ({} x{} vs {} x{})", what, set, b.binding,
                            type_name(have->descriptorType), have->descriptorCount, type_name(b.descriptorType),
                            b.descriptorCount));
  }
  have->stageFlags |= b.stageFlags;
}

// One binding per number over every source, in binding order.
std::vector<VkDescriptorSetLayoutBinding> merge_sources(
    std::span<const std::span<const shadergen::DescriptorBinding>> sources, std::uint32_t set, std::string_view what) {
  std::vector<VkDescriptorSetLayoutBinding> merged;
  for (std::span<const shadergen::DescriptorBinding> source : sources) {
    for (const VkDescriptorSetLayoutBinding& b : shadergen::vk::descriptor_set_layout_bindings(source, set)) {
      merge_binding(merged, b, set, what);
    }
  }
  std::sort(merged.begin(), merged.end(),
            [](const VkDescriptorSetLayoutBinding& a, const VkDescriptorSetLayoutBinding& b) {
              return a.binding < b.binding;
            });
  return merged;
}

}  // namespace

std::vector<VkDescriptorSetLayoutBinding> merged_set_bindings(
    std::initializer_list<std::span<const shadergen::DescriptorBinding>> sources, std::uint32_t set,
    std::string_view what) {
  return merge_sources(std::span(sources.begin(), sources.size()), set, what);
}

std::vector<VkDescriptorSetLayoutBinding> merged_set_bindings(std::span<const shadergen::Reflection* const> shaders,
                                                              std::uint32_t set, std::string_view what) {
  std::vector<std::span<const shadergen::DescriptorBinding>> sources;
  for (const shadergen::Reflection* shader : shaders) sources.push_back(shader->bindings);
  return merge_sources(sources, set, what);
}

std::vector<VkPushConstantRange> merged_push_constant_ranges(
    std::initializer_list<const shadergen::Reflection*> shaders, VkShaderStageFlags stages) {
  return merged_push_constant_ranges(std::span(shaders.begin(), shaders.size()), stages);
}

std::vector<VkPushConstantRange> merged_push_constant_ranges(std::span<const shadergen::Reflection* const> shaders,
                                                             VkShaderStageFlags stages) {
  const shadergen::Reflection* largest = nullptr;
  for (const shadergen::Reflection* shader : shaders) {
    if (largest == nullptr || shader->push_constant_size > largest->push_constant_size) largest = shader;
  }
  if (largest == nullptr) return {};
  return shadergen::vk::push_constant_ranges(*largest, stages);
}

std::uint32_t push_constant_bytes(std::span<const VkPushConstantRange> ranges) {
  std::uint32_t bytes = 0;
  for (const VkPushConstantRange& range : ranges) bytes = std::max(bytes, range.offset + range.size);
  return bytes;
}

void check_bindings(std::span<const VkDescriptorSetLayoutBinding> bindings, std::span<const VkDescriptorType> types,
                    std::string_view what) {
  bool as_bound = bindings.size() == types.size();
  for (std::size_t i = 0; as_bound && i < types.size(); ++i) {
    as_bound = bindings[i].binding == i && bindings[i].descriptorType == types[i] && bindings[i].descriptorCount == 1;
  }
  if (!as_bound) {
    std::vector<std::string> expected;
    for (std::size_t i = 0; i < types.size(); ++i) expected.push_back(fmt::format("{} {}", i, type_name(types[i])));
    std::vector<std::string> found;
    for (const VkDescriptorSetLayoutBinding& b : bindings) {
      found.push_back(fmt::format("{} {}{}", b.binding, type_name(b.descriptorType),
                                  b.descriptorCount == 1 ? "" : fmt::format("[{}]", b.descriptorCount)));
    }
    throw Error(fmt::format("{}: the shaders' reflection declares bindings ({}); the runtime binds ({})", what,
                            fmt::join(found, ", "), fmt::join(expected, ", ")));
  }
}

void check_storage_buffers(std::span<const VkDescriptorSetLayoutBinding> bindings, std::uint32_t count,
                           std::string_view what) {
  const std::vector<VkDescriptorType> types(count, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
  check_bindings(bindings, types, what);
}

}  // namespace tilelight
