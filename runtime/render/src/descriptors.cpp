#include "descriptors.h"

#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <array>

namespace tilelight {

namespace {

// Descriptors of each type per set, at most, over every set a renderer allocates: set 0 of the
// lighting interface has 1 uniform buffer and 5 images; the GPU index and tile-list builds have
// 5 storage buffers; the compute light pass's sets have 1 storage image and 1 storage buffer;
// the branch features' set (branch_set.h) 1 dynamic uniform buffer.
constexpr std::uint32_t kUniformBuffersPerSet = 4;
constexpr std::uint32_t kDynamicUniformBuffersPerSet = 1;
constexpr std::uint32_t kSampledImagesPerSet = 8;
constexpr std::uint32_t kStorageBuffersPerSet = 8;
constexpr std::uint32_t kStorageImagesPerSet = 2;

}  // namespace

UniqueDescriptorPool create_descriptor_pool(const Context& context, std::uint32_t max_sets, std::string_view name) {
  const std::array<VkDescriptorPoolSize, 5> sizes{{
      {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kUniformBuffersPerSet * max_sets},
      {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, kDynamicUniformBuffersPerSet * max_sets},
      {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kSampledImagesPerSet * max_sets},
      {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kStorageBuffersPerSet * max_sets},
      {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kStorageImagesPerSet * max_sets},
  }};
  VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  info.maxSets = max_sets;
  info.poolSizeCount = static_cast<std::uint32_t>(sizes.size());
  info.pPoolSizes = sizes.data();
  VkDescriptorPool pool = VK_NULL_HANDLE;
  check(vkCreateDescriptorPool(context.device(), &info, nullptr, &pool), "vkCreateDescriptorPool", name);
  UniqueDescriptorPool owned(pool, {context.device()});
  context.name_object(pool, name);
  return owned;
}

VkDescriptorSet allocate_descriptor_set(const Context& context, VkDescriptorPool pool, VkDescriptorSetLayout layout,
                                        std::string_view name) {
  VkDescriptorSetAllocateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  info.descriptorPool = pool;
  info.descriptorSetCount = 1;
  info.pSetLayouts = &layout;
  VkDescriptorSet set = VK_NULL_HANDLE;
  check(vkAllocateDescriptorSets(context.device(), &info, &set), "vkAllocateDescriptorSets", name);
  context.name_object(set, name);
  return set;
}

void write_buffer_descriptor(const Context& context, VkDescriptorSet set, std::uint32_t binding, VkDescriptorType type,
                             VkBuffer buffer, VkDeviceSize range) {
  const VkDescriptorBufferInfo info{buffer, 0, range};
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.dstSet = set;
  write.dstBinding = binding;
  write.descriptorCount = 1;
  write.descriptorType = type;
  write.pBufferInfo = &info;
  vkUpdateDescriptorSets(context.device(), 1, &write, 0, nullptr);
}

namespace {

void write_image_info(const Context& context, VkDescriptorSet set, std::uint32_t binding, VkDescriptorType type,
                      const VkDescriptorImageInfo& info) {
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.dstSet = set;
  write.dstBinding = binding;
  write.descriptorCount = 1;
  write.descriptorType = type;
  write.pImageInfo = &info;
  vkUpdateDescriptorSets(context.device(), 1, &write, 0, nullptr);
}

}  // namespace

void write_image_descriptor(const Context& context, VkDescriptorSet set, std::uint32_t binding, VkSampler sampler,
                            VkImageView view, VkImageLayout layout) {
  write_image_info(context, set, binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, {sampler, view, layout});
}

void write_storage_image_descriptor(const Context& context, VkDescriptorSet set, std::uint32_t binding,
                                    VkImageView view) {
  write_image_info(context, set, binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
                   {VK_NULL_HANDLE, view, VK_IMAGE_LAYOUT_GENERAL});
}

}  // namespace tilelight
