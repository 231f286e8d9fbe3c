#pragma once
// Descriptor pool and set allocation, and the kinds of writes the runtime makes.

#include "tilelight/vulkan/vk_handles.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string_view>

namespace tilelight {

class Context;

// A pool big enough for every set one renderer allocates (sets are freed with the pool).
UniqueDescriptorPool create_descriptor_pool(const Context& context, std::uint32_t max_sets, std::string_view name);

VkDescriptorSet allocate_descriptor_set(const Context& context, VkDescriptorPool pool, VkDescriptorSetLayout layout,
                                        std::string_view name);

// `range`: the bytes from the buffer's start a shader sees; a dynamic uniform buffer's must be
// its block's size (the dynamic offset moves the window, which must stay inside the buffer).
void write_buffer_descriptor(const Context& context, VkDescriptorSet set, std::uint32_t binding, VkDescriptorType type,
                             VkBuffer buffer, VkDeviceSize range = VK_WHOLE_SIZE);

void write_image_descriptor(const Context& context, VkDescriptorSet set, std::uint32_t binding, VkSampler sampler,
                            VkImageView view, VkImageLayout layout);

// A storage image, accessed in VK_IMAGE_LAYOUT_GENERAL.
void write_storage_image_descriptor(const Context& context, VkDescriptorSet set, std::uint32_t binding,
                                    VkImageView view);

}  // namespace tilelight
