// Device memory that cannot be had: the error is a VulkanError that names the call, the object
// and VK_ERROR_OUT_OF_DEVICE_MEMORY, and nothing is left half-built.
#include "tilelight/vulkan/buffer.h"
#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace tilelight::test {
namespace {

VkDeviceSize largest_heap(const Context& context) {
  const VkPhysicalDeviceMemoryProperties& props = context.memory_properties();
  VkDeviceSize largest = 0;
  for (std::uint32_t i = 0; i < props.memoryHeapCount; ++i) largest = std::max(largest, props.memoryHeaps[i].size);
  return largest;
}

// No validation layer here: asking for more than a heap holds is itself invalid usage, which the
// layer would rightly report. What is tested is the driver's answer and how the runtime passes
// it on, the same answer a real allocation beyond free memory gets.
TEST(OutOfMemory, ABufferLargerThanEveryHeapFailsNamingTheBuffer) {
  ContextOptions options;
  options.validation = false;
  const Context context(options);
  const VkDeviceSize size = largest_heap(context) * 4;
  ASSERT_GT(size, 0u);
  try {
    const Buffer buffer(context,
                        {size, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::DeviceLocal, "oversized test buffer"});
    FAIL() << "a " << size << "-byte buffer was created";
  } catch (const VulkanError& e) {
    EXPECT_EQ(e.result(), VK_ERROR_OUT_OF_DEVICE_MEMORY) << e.what();
    const std::string what = e.what();
    EXPECT_NE(what.find(" failed for oversized test buffer: VK_ERROR_OUT_OF_DEVICE_MEMORY"), std::string::npos) << what;
  }
  // The device is still usable afterwards.
  EXPECT_NO_THROW(context.wait_idle("after a failed allocation"));
  const Buffer small(context, {256, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::HostUpload, "small buffer"});
  EXPECT_TRUE(small.host_visible());
}

}  // namespace
}  // namespace tilelight::test
