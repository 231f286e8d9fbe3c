#pragma once
// Owning aliases for every Vulkan object type the runtime creates. Each one is a Handle with a
// deleter that remembers the parent needed to destroy it.

#include "tilelight/vulkan/handle.h"

#include <vulkan/vulkan.h>

namespace tilelight {

// Destroys an object that is a child of a VkDevice with the matching vkDestroy*/vkFree*.
template <typename T, void (*Destroy)(VkDevice, T, const VkAllocationCallbacks*)>
struct DeviceChildDeleter {
  VkDevice device = VK_NULL_HANDLE;
  void operator()(T handle) const noexcept { Destroy(device, handle, nullptr); }
};

struct InstanceDeleter {
  void operator()(VkInstance instance) const noexcept { vkDestroyInstance(instance, nullptr); }
};

struct DeviceDeleter {
  void operator()(VkDevice device) const noexcept { vkDestroyDevice(device, nullptr); }
};

// The messenger's destroy function is an extension entry point that the loader does not
// export, so the deleter carries the pointer fetched from the instance.
struct DebugMessengerDeleter {
  VkInstance instance = VK_NULL_HANDLE;
  PFN_vkDestroyDebugUtilsMessengerEXT destroy = nullptr;
  void operator()(VkDebugUtilsMessengerEXT messenger) const noexcept { destroy(instance, messenger, nullptr); }
};

// Command buffers return to their pool; the pool must outlive them.
struct CommandBufferDeleter {
  VkDevice device = VK_NULL_HANDLE;
  VkCommandPool pool = VK_NULL_HANDLE;
  void operator()(VkCommandBuffer buffer) const noexcept { vkFreeCommandBuffers(device, pool, 1, &buffer); }
};

using UniqueInstance = Handle<VkInstance, InstanceDeleter>;
using UniqueDevice = Handle<VkDevice, DeviceDeleter>;
using UniqueDebugMessenger = Handle<VkDebugUtilsMessengerEXT, DebugMessengerDeleter>;
using UniqueCommandBuffer = Handle<VkCommandBuffer, CommandBufferDeleter>;

using UniqueBuffer = Handle<VkBuffer, DeviceChildDeleter<VkBuffer, &vkDestroyBuffer>>;
using UniqueImage = Handle<VkImage, DeviceChildDeleter<VkImage, &vkDestroyImage>>;
using UniqueImageView = Handle<VkImageView, DeviceChildDeleter<VkImageView, &vkDestroyImageView>>;
using UniqueSampler = Handle<VkSampler, DeviceChildDeleter<VkSampler, &vkDestroySampler>>;
using UniqueDeviceMemory = Handle<VkDeviceMemory, DeviceChildDeleter<VkDeviceMemory, &vkFreeMemory>>;
using UniqueCommandPool = Handle<VkCommandPool, DeviceChildDeleter<VkCommandPool, &vkDestroyCommandPool>>;
using UniqueFence = Handle<VkFence, DeviceChildDeleter<VkFence, &vkDestroyFence>>;
using UniqueSemaphore = Handle<VkSemaphore, DeviceChildDeleter<VkSemaphore, &vkDestroySemaphore>>;
using UniqueQueryPool = Handle<VkQueryPool, DeviceChildDeleter<VkQueryPool, &vkDestroyQueryPool>>;
using UniquePipeline = Handle<VkPipeline, DeviceChildDeleter<VkPipeline, &vkDestroyPipeline>>;
using UniquePipelineLayout = Handle<VkPipelineLayout, DeviceChildDeleter<VkPipelineLayout, &vkDestroyPipelineLayout>>;
using UniquePipelineCache = Handle<VkPipelineCache, DeviceChildDeleter<VkPipelineCache, &vkDestroyPipelineCache>>;
using UniqueDescriptorSetLayout =
    Handle<VkDescriptorSetLayout, DeviceChildDeleter<VkDescriptorSetLayout, &vkDestroyDescriptorSetLayout>>;
using UniqueDescriptorPool = Handle<VkDescriptorPool, DeviceChildDeleter<VkDescriptorPool, &vkDestroyDescriptorPool>>;
using UniqueShaderModule = Handle<VkShaderModule, DeviceChildDeleter<VkShaderModule, &vkDestroyShaderModule>>;
using UniqueRenderPass = Handle<VkRenderPass, DeviceChildDeleter<VkRenderPass, &vkDestroyRenderPass>>;
using UniqueFramebuffer = Handle<VkFramebuffer, DeviceChildDeleter<VkFramebuffer, &vkDestroyFramebuffer>>;

}  // namespace tilelight
