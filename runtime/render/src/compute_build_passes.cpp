#include "compute_build_passes.h"

#include "tilelight/vulkan/barriers.h"

#include <array>

namespace tilelight {

ComputeBuildBuffers create_compute_build_buffers(const Context& context, std::span<const std::uint8_t> class_for_raw,
                                                 std::span<const bool> pruned, VkDeviceSize counter_bytes,
                                                 const std::string& name) {
  constexpr std::uint32_t kNoClass = 0xFF;  // the shaders' NO_CLASS
  std::array<std::uint32_t, 256> lut{};
  lut.fill(kNoClass);
  for (std::size_t raw = 0; raw < class_for_raw.size(); ++raw) {
    if (!pruned[raw]) lut[raw] = class_for_raw[raw];
  }
  ComputeBuildBuffers b;
  b.lut = Buffer(context, {sizeof(lut), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::HostUpload, name + " LUT"});
  b.lut.write_values(std::span<const std::uint32_t>(lut));
  b.counters = Buffer(context, {counter_bytes,
                                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                                    VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                MemoryUse::DeviceLocal, name + " counters"});
  b.host_counters = Buffer(context, {counter_bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::HostReadback,
                                     name + " counters (host copy)"});
  return b;
}

void record_compute_build(VkCommandBuffer cmd, const ComputeBuildPasses& b) {
  const Scope compute_rw{VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT};
  vkCmdFillBuffer(cmd, b.counters, 0, VK_WHOLE_SIZE, 0);
  buffer_barrier(cmd, b.counters, {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT}, compute_rw);

  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, b.layout, 0, 1, &b.set, 0, nullptr);
  vkCmdPushConstants(cmd, b.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, static_cast<std::uint32_t>(b.push.size_bytes()),
                     b.push.data());
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, b.count);
  vkCmdDispatch(cmd, b.groups, 1, 1);
  memory_barrier(cmd, compute_rw, compute_rw);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, b.prefix);
  vkCmdDispatch(cmd, 1, 1, 1);
  memory_barrier(cmd, compute_rw, compute_rw);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, b.fill);
  vkCmdDispatch(cmd, b.groups, 1, 1);

  memory_barrier(cmd, compute_rw,
                 {b.consumer_stages | VK_PIPELINE_STAGE_TRANSFER_BIT, b.consumer_access | VK_ACCESS_TRANSFER_READ_BIT});
  const VkBufferCopy copy{0, 0, b.counter_bytes};
  vkCmdCopyBuffer(cmd, b.counters, b.host_counters, 1, &copy);
  buffer_barrier(cmd, b.host_counters, {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT},
                 {VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT});
}

}  // namespace tilelight
