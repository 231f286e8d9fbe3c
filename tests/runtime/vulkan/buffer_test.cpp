// Buffers: persistent mapping, bounds-checked host access, GPU writes visible after readback.
#include "tilelight_testing/test_support.h"

#include "tilelight/vulkan/barriers.h"
#include "tilelight/vulkan/buffer.h"
#include "tilelight/vulkan/error.h"
#include "tilelight/vulkan/submit.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

namespace tilelight {
namespace {

using test::VulkanTest;

TEST_F(VulkanTest, MappedBufferWriteThenRead) {
  Buffer buffer(context(), {256, VK_BUFFER_USAGE_INDEX_BUFFER_BIT, MemoryUse::HostUpload, "tile index buffer"});
  ASSERT_TRUE(buffer.host_visible());
  EXPECT_EQ(buffer.size(), 256u);
  const std::array<std::uint32_t, 4> values = {1, 2, 3, 0xdeadbeef};
  buffer.write_values(std::span<const std::uint32_t>(values), 16);
  std::array<std::uint32_t, 4> back{};
  buffer.read(std::as_writable_bytes(std::span(back)), 16);
  EXPECT_EQ(back, values);
  EXPECT_EQ(buffer.as<std::uint32_t>().size(), 64u);
  EXPECT_EQ(buffer.as<std::uint32_t>()[7], 0xdeadbeefu);
}

TEST_F(VulkanTest, OutOfRangeAccessNamesTheBuffer) {
  Buffer buffer(context(), {16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::HostUpload, "indirect records"});
  const std::array<std::byte, 8> data{};
  try {
    buffer.write(data, 12);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "cannot write 8 bytes at offset 12 of buffer indirect records (16 bytes)");
  }
  EXPECT_THROW(buffer.write(data, 1u << 20), Error);
}

TEST_F(VulkanTest, DeviceLocalBufferIsNotMapped) {
  Buffer buffer(context(), {64, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::DeviceLocal, "tile IDs"});
  EXPECT_FALSE(buffer.host_visible());
  EXPECT_THROW((void)buffer.bytes(), Error);
}

TEST_F(VulkanTest, ZeroSizedBufferIsRejected) {
  EXPECT_THROW(Buffer(context(), {0, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::HostUpload, "empty"}), Error);
}

TEST_F(VulkanTest, GpuFillIsVisibleToTheHost) {
  Buffer buffer(context(), {64, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::HostReadback, "fill target"});
  submit_and_wait(
      context(), pool(),
      [&](VkCommandBuffer cmd) {
        vkCmdFillBuffer(cmd, buffer.handle(), 0, VK_WHOLE_SIZE, 0x01020304u);
        buffer_barrier(cmd, buffer.handle(), {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT},
                       {VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT});
      },
      "filling a buffer", Seconds{30.0});
  for (const std::uint32_t word : buffer.as<std::uint32_t>()) {
    EXPECT_EQ(word, 0x01020304u);
  }
}

TEST_F(VulkanTest, MovedBufferKeepsItsMapping) {
  Buffer a(context(), {32, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, MemoryUse::HostUpload, "a"});
  a.as<std::uint32_t>()[0] = 42;
  Buffer b(std::move(a));
  EXPECT_FALSE(a.host_visible());
  EXPECT_EQ(a.handle(), VK_NULL_HANDLE);
  EXPECT_EQ(b.as<std::uint32_t>()[0], 42u);
  Buffer c;
  c = std::move(b);
  EXPECT_EQ(c.as<std::uint32_t>()[0], 42u);
}

}  // namespace
}  // namespace tilelight
