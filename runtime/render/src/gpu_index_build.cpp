#include "gpu_index_build.h"

#include "shader_registry.h"
#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <array>

namespace tilelight {
namespace {

// Mirrors tile_rects.glsl.
constexpr std::uint32_t kMaxDrawClasses = 128;
// primitives, rectangles, tiles, cursor (kMaxDrawClasses each), invalid_tiles.
constexpr VkDeviceSize kCountersBytes = (4 * kMaxDrawClasses + 1) * sizeof(std::uint32_t);
constexpr VkDeviceSize kDrawRecordBytes = sizeof(VkDrawIndexedIndirectCommand);
// constant_ids of tile_rects.comp (FILL_PASS, COALESCE) and tile_rects.glsl (POINT_PRIMITIVES).
constexpr std::uint32_t kFillPass = 0, kCoalesce = 1, kPoints = 2;

}  // namespace

GpuIndexBuild::GpuIndexBuild(const Context& context, const shadergen::Registry& shaders, const TileGrid& grid,
                             std::span<const std::uint8_t> class_for_raw, std::span<const bool> pruned,
                             std::uint32_t class_count, bool coalesce, TilePrimitive primitive, const Buffer& tile_ids,
                             VkDescriptorPool pool)
    : class_count_(class_count) {
  if (class_count > kMaxDrawClasses) throw Error("the GPU index build supports at most 128 draw classes");
  indices_ = Buffer(context, {std::max<VkDeviceSize>(grid.max_index_count(), 6) * sizeof(std::uint32_t),
                              VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDEX_BUFFER_BIT,
                              MemoryUse::DeviceLocal, "tile indices (GPU-built)"});
  draws_ = Buffer(context, {kMaxDrawClasses * kDrawRecordBytes,
                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT,
                            MemoryUse::DeviceLocal, "indirect draws (GPU-built)"});

  const shadergen::Permutation& rects = light_companions(shaders).tile_rects.shader;
  const std::uint32_t points = primitive == TilePrimitive::points ? 1 : 0;
  const std::uint32_t coalescing = coalesce ? 1 : 0;
  ComputeBuildDesc desc{
      .name = "GPU index build",
      .counter_bytes = kCountersBytes,
      .outputs = {indices_.handle(), draws_.handle()},
      .count = {&rects, SpecConstants{}.set(kFillPass, 0).set(kCoalesce, coalescing).set(kPoints, points)},
      .prefix = {&light_companions(shaders).tile_prefix.shader, SpecConstants{}.set(kPoints, points)},
      .fill = {&rects, SpecConstants{}.set(kFillPass, 1).set(kCoalesce, coalescing).set(kPoints, points)},
      .push = {grid.tiles_x, grid.tiles_y, grid.blocks_x, grid.blocks_y, class_count, 0, 0, 0},
      .groups = workgroups(grid.block_count(), rects),
      .consumer = {VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_VERTEX_INPUT_BIT,
                   VK_ACCESS_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_INDEX_READ_BIT}};
  build_ = ComputeBuild(context, pool, {tile_ids.handle(), class_for_raw, pruned}, std::move(desc));
}

void GpuIndexBuild::record(VkCommandBuffer cmd) const { build_.record(cmd); }

GpuIndexBuild::Counts GpuIndexBuild::read_counts() const {
  const std::span<const std::uint32_t> values = build_.host_counters();
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
