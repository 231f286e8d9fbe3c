#include "gpu_index_build.h"

#include "compute_build_passes.h"
#include "descriptors.h"
#include "pipelines.h"
#include "shader_registry.h"
#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <split_second_shaders.h>

#include <array>

namespace tilelight {
namespace {

// Mirrors tile_rects.glsl.
constexpr std::uint32_t kMaxDrawClasses = 128;
// primitives, rectangles, tiles, cursor (kMaxDrawClasses each), invalid_tiles.
constexpr VkDeviceSize kCountersBytes = (4 * kMaxDrawClasses + 1) * sizeof(std::uint32_t);
constexpr VkDeviceSize kDrawRecordBytes = sizeof(VkDrawIndexedIndirectCommand);
constexpr std::uint32_t kBlocksPerGroup = 128;  // local_size_x of tile_rects.comp

}  // namespace

GpuIndexBuild::GpuIndexBuild(const Context& context, const shadergen::Registry& shaders, const TileGrid& grid,
                             std::span<const std::uint8_t> class_for_raw, std::span<const bool> pruned,
                             std::uint32_t class_count, bool coalesce, TilePrimitive primitive, const Buffer& tile_ids,
                             VkDescriptorPool pool)
    : grid_(grid), class_count_(class_count) {
  if (class_count > kMaxDrawClasses) throw Error("the GPU index build supports at most 128 draw classes");
  buffers_ = create_compute_build_buffers(context, class_for_raw, pruned, kCountersBytes, "GPU build");
  indices_ = Buffer(context, {std::max<VkDeviceSize>(grid.max_index_count(), 6) * sizeof(std::uint32_t),
                              VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDEX_BUFFER_BIT,
                              MemoryUse::DeviceLocal, "tile indices (GPU-built)"});
  draws_ = Buffer(context, {kMaxDrawClasses * kDrawRecordBytes,
                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT,
                            MemoryUse::DeviceLocal, "indirect draws (GPU-built)"});

  std::array<VkDescriptorSetLayoutBinding, 5> bindings{};
  for (std::uint32_t i = 0; i < bindings.size(); ++i) {
    bindings[i] = {i, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
  }
  set_layout_ = create_descriptor_set_layout(context, bindings, "GPU index build set layout");
  const VkDescriptorSetLayout set_layouts[] = {set_layout_.get()};
  const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, 32};
  layout_ = create_pipeline_layout(context, set_layouts, std::span(&push, 1), "GPU index build layout");
  set_ = allocate_descriptor_set(context, pool, set_layout_.get(), "GPU index build set");
  const std::array<VkBuffer, 5> buffers{tile_ids.handle(), buffers_.lut.handle(), buffers_.counters.handle(),
                                        indices_.handle(), draws_.handle()};
  for (std::uint32_t i = 0; i < buffers.size(); ++i) {
    write_buffer_descriptor(context, set_, i, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, buffers[i]);
  }

  const std::uint32_t points = primitive == TilePrimitive::points ? 1 : 0;
  count_ = create_compute_pipeline(context, layout_.get(), companion_spirv(shaders, "tile_rects"),
                                   SpecConstants{}.set(0, 0).set(1, coalesce ? 1 : 0).set(2, points),
                                   "GPU index build: count");
  prefix_ = create_compute_pipeline(context, layout_.get(), companion_spirv(shaders, "tile_prefix"),
                                    SpecConstants{}.set(2, points), "GPU index build: prefix sum");
  fill_ = create_compute_pipeline(context, layout_.get(), companion_spirv(shaders, "tile_rects"),
                                  SpecConstants{}.set(0, 1).set(1, coalesce ? 1 : 0).set(2, points),
                                  "GPU index build: fill");
}

void GpuIndexBuild::record(VkCommandBuffer cmd) const {
  const std::array<std::uint32_t, 8> push{
      grid_.tiles_x, grid_.tiles_y, grid_.blocks_x, grid_.blocks_y, class_count_, 0, 0, 0};
  ComputeBuildPasses build;
  build.layout = layout_.get();
  build.set = set_;
  build.push = push;
  build.count = count_.get();
  build.prefix = prefix_.get();
  build.fill = fill_.get();
  build.groups = (grid_.block_count() + kBlocksPerGroup - 1) / kBlocksPerGroup;
  build.counters = buffers_.counters.handle();
  build.host_counters = buffers_.host_counters.handle();
  build.counter_bytes = kCountersBytes;
  build.consumer_stages = VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_VERTEX_INPUT_BIT;
  build.consumer_access = VK_ACCESS_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_INDEX_READ_BIT;
  record_compute_build(cmd, build);
}

GpuIndexBuild::Counts GpuIndexBuild::read_counts() const {
  const std::span<const std::uint32_t> values = buffers_.host_counters.as<const std::uint32_t>();
  Counts counts;
  const auto per_class = [&](std::uint32_t array) {
    const auto first = values.begin() + std::ptrdiff_t{array} * kMaxDrawClasses;
    return std::vector<std::uint32_t>(first, first + class_count_);
  };
  counts.primitives = per_class(0);
  counts.rectangles = per_class(1);
  counts.tiles = per_class(2);
  counts.invalid_tiles = values[std::size_t{4} * kMaxDrawClasses];
  return counts;
}

}  // namespace tilelight
