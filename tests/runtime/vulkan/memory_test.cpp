// Memory-type choice on a made-up device with typical discrete-GPU memory types.
#include "tilelight/vulkan/memory.h"
#include "tilelight/vulkan/error.h"

#include <gtest/gtest.h>

namespace tilelight {
namespace {

VkPhysicalDeviceMemoryProperties discrete_gpu() {
  VkPhysicalDeviceMemoryProperties props{};
  props.memoryTypeCount = 4;
  props.memoryTypes[0].propertyFlags = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
  props.memoryTypes[1].propertyFlags = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  props.memoryTypes[2].propertyFlags =
      VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT | VK_MEMORY_PROPERTY_HOST_CACHED_BIT;
  props.memoryTypes[3].propertyFlags = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT;  // not coherent
  return props;
}

TEST(Memory, EachUseGetsItsPreferredType) {
  const auto props = discrete_gpu();
  EXPECT_EQ(choose_memory_type(props, 0xf, MemoryUse::DeviceLocal, "x"), 0u);
  EXPECT_EQ(choose_memory_type(props, 0xf, MemoryUse::HostUpload, "x"), 1u);
  EXPECT_EQ(choose_memory_type(props, 0xf, MemoryUse::HostReadback, "x"), 2u);
}

TEST(Memory, FallsBackWithinTheAllowedTypes) {
  const auto props = discrete_gpu();
  // Device-local not allowed: any allowed type will do.
  EXPECT_EQ(choose_memory_type(props, 0b0010, MemoryUse::DeviceLocal, "x"), 1u);
  // Cached not allowed: coherent uncached is still fine for readback.
  EXPECT_EQ(choose_memory_type(props, 0b0011, MemoryUse::HostReadback, "x"), 1u);
}

TEST(Memory, NoFittingTypeNamesTheResource) {
  const auto props = discrete_gpu();
  try {
    choose_memory_type(props, 0b1001, MemoryUse::HostUpload, "tile index buffer");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "no host-upload (host-visible, coherent) memory type is allowed for tile index "
                 "buffer (memoryTypeBits 0x9)");
  }
}

}  // namespace
}  // namespace tilelight
