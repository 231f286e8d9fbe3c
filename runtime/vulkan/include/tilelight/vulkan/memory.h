#pragma once
// Device-memory allocation. The runtime allocates one VkDeviceMemory per resource: it creates a
// few dozen long-lived resources, far below maxMemoryAllocationCount (4096 on every driver
// that matters), so a sub-allocator would add code without benefit.

#include "tilelight/vulkan/vk_handles.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <optional>
#include <string_view>

namespace tilelight {

class Context;

// What the memory of a buffer or image is for; decides the memory type.
enum class MemoryUse {
  DeviceLocal,   // GPU only: prefers DEVICE_LOCAL, accepts any type the resource allows
  HostUpload,    // written by the CPU, read by the GPU: HOST_VISIBLE | HOST_COHERENT, mapped
  HostReadback,  // written by the GPU, read by the CPU: HOST_VISIBLE | HOST_COHERENT, mapped,
                 // HOST_CACHED preferred (uncached reads are slow on discrete GPUs)
};

bool is_host_visible(MemoryUse use);

// The first memory type allowed by `type_bits` that has every flag in `required`; nullopt if
// none. Drivers order memory types best-first, so the first match is the one to take.
std::optional<std::uint32_t> find_memory_type(const VkPhysicalDeviceMemoryProperties& props, std::uint32_t type_bits,
                                              VkMemoryPropertyFlags required);

// The memory type for `use`, applying its preferences; throws tilelight::Error naming `object`
// when no allowed type fits.
std::uint32_t choose_memory_type(const VkPhysicalDeviceMemoryProperties& props, std::uint32_t type_bits, MemoryUse use,
                                 std::string_view object);

// Allocates memory for a resource with `requirements`. `object` names the resource in errors
// ("vkAllocateMemory failed for G-buffer RT1: VK_ERROR_OUT_OF_DEVICE_MEMORY") and in
// validation messages.
UniqueDeviceMemory allocate_memory(const Context& context, const VkMemoryRequirements& requirements, MemoryUse use,
                                   std::string_view object);

}  // namespace tilelight
