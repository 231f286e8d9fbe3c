#include "descriptors.h"

#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <array>

namespace tilelight {

UniqueDescriptorPool create_descriptor_pool(const Context& context, std::uint32_t max_sets, std::string_view name) {
  const std::array<VkDescriptorPoolSize, 3> sizes{{
      {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 4 * max_sets},
      {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 8 * max_sets},
      {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 8 * max_sets},
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
                             VkBuffer buffer) {
  const VkDescriptorBufferInfo info{buffer, 0, VK_WHOLE_SIZE};
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.dstSet = set;
  write.dstBinding = binding;
  write.descriptorCount = 1;
  write.descriptorType = type;
  write.pBufferInfo = &info;
  vkUpdateDescriptorSets(context.device(), 1, &write, 0, nullptr);
}

void write_image_descriptor(const Context& context, VkDescriptorSet set, std::uint32_t binding, VkSampler sampler,
                            VkImageView view, VkImageLayout layout) {
  const VkDescriptorImageInfo info{sampler, view, layout};
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.dstSet = set;
  write.dstBinding = binding;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  write.pImageInfo = &info;
  vkUpdateDescriptorSets(context.device(), 1, &write, 0, nullptr);
}

}  // namespace tilelight
