#pragma once
// The VkObjectType of each Vulkan handle type, for debug names (vkSetDebugUtilsObjectNameEXT).
// A handle type without an entry here fails to compile instead of silently losing its name.

#include <vulkan/vulkan.h>

namespace tilelight {

template <typename T>
struct ObjectType;

// On 64-bit targets every handle type is a distinct pointer type, which this table relies on
// (32-bit targets, where non-dispatchable handles are all uint64_t, are not supported).
static_assert(sizeof(void*) == 8, "tilelight needs a 64-bit target");

#define TILELIGHT_OBJECT_TYPE(Handle, Value)     \
  template <>                                    \
  struct ObjectType<Handle> {                    \
    static constexpr VkObjectType value = Value; \
  };

TILELIGHT_OBJECT_TYPE(VkQueue, VK_OBJECT_TYPE_QUEUE)
TILELIGHT_OBJECT_TYPE(VkBuffer, VK_OBJECT_TYPE_BUFFER)
TILELIGHT_OBJECT_TYPE(VkImage, VK_OBJECT_TYPE_IMAGE)
TILELIGHT_OBJECT_TYPE(VkImageView, VK_OBJECT_TYPE_IMAGE_VIEW)
TILELIGHT_OBJECT_TYPE(VkDeviceMemory, VK_OBJECT_TYPE_DEVICE_MEMORY)
TILELIGHT_OBJECT_TYPE(VkSampler, VK_OBJECT_TYPE_SAMPLER)
TILELIGHT_OBJECT_TYPE(VkCommandPool, VK_OBJECT_TYPE_COMMAND_POOL)
TILELIGHT_OBJECT_TYPE(VkCommandBuffer, VK_OBJECT_TYPE_COMMAND_BUFFER)
TILELIGHT_OBJECT_TYPE(VkFence, VK_OBJECT_TYPE_FENCE)
TILELIGHT_OBJECT_TYPE(VkSemaphore, VK_OBJECT_TYPE_SEMAPHORE)
TILELIGHT_OBJECT_TYPE(VkQueryPool, VK_OBJECT_TYPE_QUERY_POOL)
TILELIGHT_OBJECT_TYPE(VkPipeline, VK_OBJECT_TYPE_PIPELINE)
TILELIGHT_OBJECT_TYPE(VkPipelineLayout, VK_OBJECT_TYPE_PIPELINE_LAYOUT)
TILELIGHT_OBJECT_TYPE(VkPipelineCache, VK_OBJECT_TYPE_PIPELINE_CACHE)
TILELIGHT_OBJECT_TYPE(VkDescriptorSetLayout, VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT)
TILELIGHT_OBJECT_TYPE(VkDescriptorPool, VK_OBJECT_TYPE_DESCRIPTOR_POOL)
TILELIGHT_OBJECT_TYPE(VkDescriptorSet, VK_OBJECT_TYPE_DESCRIPTOR_SET)
TILELIGHT_OBJECT_TYPE(VkShaderModule, VK_OBJECT_TYPE_SHADER_MODULE)
TILELIGHT_OBJECT_TYPE(VkRenderPass, VK_OBJECT_TYPE_RENDER_PASS)
TILELIGHT_OBJECT_TYPE(VkFramebuffer, VK_OBJECT_TYPE_FRAMEBUFFER)

#undef TILELIGHT_OBJECT_TYPE

}  // namespace tilelight
