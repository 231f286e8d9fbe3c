#include "reflected_layout.h"

#include "tilelight/vulkan/error.h"

#include <fmt/format.h>
#include <shadergen/vulkan.h>

#include <algorithm>

namespace tilelight {
namespace {

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
    throw Error(fmt::format("{}: the shaders disagree on set {} binding {} (descriptor type {} x{} vs {} x{})", what,
                            set, b.binding, static_cast<int>(have->descriptorType), have->descriptorCount,
                            static_cast<int>(b.descriptorType), b.descriptorCount));
  }
  have->stageFlags |= b.stageFlags;
}

}  // namespace

std::vector<VkDescriptorSetLayoutBinding> merged_set_bindings(
    std::initializer_list<std::span<const shadergen::DescriptorBinding>> sources, std::uint32_t set,
    std::string_view what) {
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

std::vector<VkPushConstantRange> merged_push_constant_ranges(
    std::initializer_list<const shadergen::Reflection*> shaders, VkShaderStageFlags stages) {
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

void check_storage_buffers(std::span<const VkDescriptorSetLayoutBinding> bindings, std::uint32_t count,
                           std::string_view what) {
  bool as_bound = bindings.size() == count;
  for (std::uint32_t i = 0; as_bound && i < count; ++i) {
    as_bound = bindings[i].binding == i && bindings[i].descriptorType == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER &&
               bindings[i].descriptorCount == 1;
  }
  if (!as_bound) {
    throw Error(
        fmt::format("{}: the shaders' reflection has {} bindings in the set; the runtime binds {} storage "
                    "buffers at bindings 0..{}",
                    what, bindings.size(), count, count - 1));
  }
}

}  // namespace tilelight
