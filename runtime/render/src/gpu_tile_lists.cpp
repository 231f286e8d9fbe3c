#include "gpu_tile_lists.h"

#include "shader_registry.h"
#include "tilelight/tiles/tile_list_builder.h"
#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <array>

namespace tilelight {
namespace {

// Mirrors tile_lists.comp.
constexpr std::uint32_t kPassConstant = 0;  // constant_id of PASS
constexpr std::uint32_t kPassCount = 0, kPassPrefix = 1, kPassFill = 2;
// tiles, cursor (kTileListMaxClasses each), invalid_tiles.
constexpr VkDeviceSize kCountersBytes = (2 * kTileListMaxClasses + 1) * sizeof(std::uint32_t);
constexpr VkDeviceSize kDispatchRecordBytes = sizeof(VkDispatchIndirectCommand);

}  // namespace

GpuTileLists::GpuTileLists(const Context& context, const shadergen::Registry& shaders, const TileGrid& grid,
                           std::span<const std::uint8_t> class_for_raw, std::span<const bool> pruned,
                           std::uint32_t class_count, std::uint32_t tiles_per_group, const Buffer& tile_ids,
                           VkDescriptorPool pool)
    : class_count_(class_count) {
  if (class_count > kTileListMaxClasses) throw Error("the GPU tile-list build supports at most 128 draw classes");
  check_tile_list_grid(grid);
  lists_ = Buffer(context, {(kTileListHeaderWords + std::size_t{grid.tile_count()}) * sizeof(std::uint32_t),
                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::DeviceLocal, "tile lists (GPU-built)"});
  dispatches_ = Buffer(context, {kTileListMaxClasses * kDispatchRecordBytes,
                                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT,
                                 MemoryUse::DeviceLocal, "indirect dispatches (GPU-built)"});

  // One shader, three passes: its PASS constant picks the pass.
  const shadergen::Permutation& lists = light_companions(shaders).tile_lists.shader;
  ComputeBuildDesc desc{
      .name = "GPU tile-list build",
      .counter_bytes = kCountersBytes,
      .outputs = {lists_.handle(), dispatches_.handle()},
      .count = {&lists, SpecConstants{}.set(kPassConstant, kPassCount)},
      .prefix = {&lists, SpecConstants{}.set(kPassConstant, kPassPrefix)},
      .fill = {&lists, SpecConstants{}.set(kPassConstant, kPassFill)},
      .push = {grid.tiles_x, grid.tiles_y, grid.blocks_x, grid.blocks_y, class_count, tiles_per_group, 0, 0},
      .groups = workgroups(grid.block_count() * kBlockTiles, lists),
      .consumer = {VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                   VK_ACCESS_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_SHADER_READ_BIT}};
  build_ = ComputeBuild(context, pool, {tile_ids.handle(), class_for_raw, pruned}, std::move(desc));
}

void GpuTileLists::record(VkCommandBuffer cmd) const { build_.record(cmd); }

GpuTileLists::Counts GpuTileLists::read_counts() const {
  const std::span<const std::uint32_t> values = build_.host_counters();
  Counts counts;
  counts.tiles.assign(values.begin(), values.begin() + class_count_);
  counts.invalid_tiles = values[std::size_t{2} * kTileListMaxClasses];
  return counts;
}

}  // namespace tilelight
