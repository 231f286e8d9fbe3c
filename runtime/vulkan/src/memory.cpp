#include "tilelight/vulkan/memory.h"

#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <fmt/format.h>

namespace tilelight {
namespace {

constexpr VkMemoryPropertyFlags kHostMappable =
    VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;

std::string_view use_name(MemoryUse use) {
  switch (use) {
    case MemoryUse::DeviceLocal: return "device-local";
    case MemoryUse::HostUpload: return "host-upload (host-visible, coherent)";
    case MemoryUse::HostReadback: return "host-readback (host-visible, coherent)";
  }
  return "?";
}

}  // namespace

bool is_host_visible(MemoryUse use) { return use != MemoryUse::DeviceLocal; }

std::optional<std::uint32_t> find_memory_type(const VkPhysicalDeviceMemoryProperties& props, std::uint32_t type_bits,
                                              VkMemoryPropertyFlags required) {
  for (std::uint32_t i = 0; i < props.memoryTypeCount; ++i) {
    const bool allowed = (type_bits & (1u << i)) != 0;
    if (allowed && (props.memoryTypes[i].propertyFlags & required) == required) {
      return i;
    }
  }
  return std::nullopt;
}

std::uint32_t choose_memory_type(const VkPhysicalDeviceMemoryProperties& props, std::uint32_t type_bits, MemoryUse use,
                                 std::string_view object) {
  std::optional<std::uint32_t> type;
  switch (use) {
    case MemoryUse::DeviceLocal:
      type = find_memory_type(props, type_bits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
      if (!type) {
        type = find_memory_type(props, type_bits, 0);
      }
      break;
    case MemoryUse::HostUpload: type = find_memory_type(props, type_bits, kHostMappable); break;
    case MemoryUse::HostReadback:
      type = find_memory_type(props, type_bits, kHostMappable | VK_MEMORY_PROPERTY_HOST_CACHED_BIT);
      if (!type) {
        type = find_memory_type(props, type_bits, kHostMappable);
      }
      break;
  }
  if (!type) {
    throw Error(
        fmt::format("no {} memory type is allowed for {} (memoryTypeBits {:#x})", use_name(use), object, type_bits));
  }
  return *type;
}

UniqueDeviceMemory allocate_memory(const Context& context, const VkMemoryRequirements& requirements, MemoryUse use,
                                   std::string_view object) {
  VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  info.allocationSize = requirements.size;
  info.memoryTypeIndex = choose_memory_type(context.memory_properties(), requirements.memoryTypeBits, use, object);
  VkDeviceMemory memory = VK_NULL_HANDLE;
  check(vkAllocateMemory(context.device(), &info, nullptr, &memory), "vkAllocateMemory", object);
  UniqueDeviceMemory owned(memory, {context.device()});
  context.name_object(memory, object);
  return owned;
}

}  // namespace tilelight
