#include "gpu_tile_lists.h"

#include "compute_build_passes.h"
#include "descriptors.h"
#include "pipelines.h"
#include "shader_registry.h"
#include "tilelight/tiles/tile_list_builder.h"
#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <array>

namespace tilelight {
namespace {

// Mirrors tile_lists.comp.
constexpr std::uint32_t kPassCount = 0, kPassPrefix = 1, kPassFill = 2;  // constant_id 0: PASS
constexpr std::uint32_t kRowsPerGroup = 128;                             // local_size_x
// tiles, cursor (kTileListMaxClasses each), invalid_tiles.
constexpr VkDeviceSize kCountersBytes = (2 * kTileListMaxClasses + 1) * sizeof(std::uint32_t);
constexpr VkDeviceSize kDispatchRecordBytes = sizeof(VkDispatchIndirectCommand);
constexpr std::uint32_t kBindings = 5;  // tile IDs, LUT, counters, lists, dispatches

}  // namespace

GpuTileLists::GpuTileLists(const Context& context, const shadergen::Registry& shaders, const TileGrid& grid,
                           std::span<const std::uint8_t> class_for_raw, std::span<const bool> pruned,
                           std::uint32_t class_count, std::uint32_t tiles_per_group, const Buffer& tile_ids,
                           VkDescriptorPool pool)
    : grid_(grid), class_count_(class_count), tiles_per_group_(tiles_per_group) {
  if (class_count > kTileListMaxClasses) throw Error("the GPU tile-list build supports at most 128 draw classes");
  check_tile_list_grid(grid);
  buffers_ = create_compute_build_buffers(context, class_for_raw, pruned, kCountersBytes, "tile-list");
  lists_ = Buffer(context, {(kTileListHeaderWords + std::size_t{grid.tile_count()}) * sizeof(std::uint32_t),
                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::DeviceLocal, "tile lists (GPU-built)"});
  dispatches_ = Buffer(context, {kTileListMaxClasses * kDispatchRecordBytes,
                                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT,
                                 MemoryUse::DeviceLocal, "indirect dispatches (GPU-built)"});

  std::array<VkDescriptorSetLayoutBinding, kBindings> bindings{};
  for (std::uint32_t i = 0; i < kBindings; ++i) {
    bindings[i] = {i, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
  }
  set_layout_ = create_descriptor_set_layout(context, bindings, "GPU tile-list build set layout");
  const VkDescriptorSetLayout set_layouts[] = {set_layout_.get()};
  const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, 8 * sizeof(std::uint32_t)};
  layout_ = create_pipeline_layout(context, set_layouts, std::span(&push, 1), "GPU tile-list build layout");
  set_ = allocate_descriptor_set(context, pool, set_layout_.get(), "GPU tile-list build set");
  const std::array<VkBuffer, kBindings> buffers{tile_ids.handle(), buffers_.lut.handle(), buffers_.counters.handle(),
                                                lists_.handle(), dispatches_.handle()};
  for (std::uint32_t i = 0; i < kBindings; ++i) {
    write_buffer_descriptor(context, set_, i, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, buffers[i]);
  }
  const std::span<const std::uint32_t> spirv = companion_spirv(shaders, "tile_lists");
  count_ = create_compute_pipeline(context, layout_.get(), spirv, SpecConstants{}.set(0, kPassCount),
                                   "GPU tile-list build: count");
  prefix_ = create_compute_pipeline(context, layout_.get(), spirv, SpecConstants{}.set(0, kPassPrefix),
                                    "GPU tile-list build: prefix sum");
  fill_ = create_compute_pipeline(context, layout_.get(), spirv, SpecConstants{}.set(0, kPassFill),
                                  "GPU tile-list build: fill");
}

void GpuTileLists::record(VkCommandBuffer cmd) const {
  const std::array<std::uint32_t, 8> push{
      grid_.tiles_x, grid_.tiles_y, grid_.blocks_x, grid_.blocks_y, class_count_, tiles_per_group_, 0, 0};
  ComputeBuildPasses build;
  build.layout = layout_.get();
  build.set = set_;
  build.push = push;
  build.count = count_.get();
  build.prefix = prefix_.get();
  build.fill = fill_.get();
  build.groups = (grid_.block_count() * kBlockTiles + kRowsPerGroup - 1) / kRowsPerGroup;
  build.counters = buffers_.counters.handle();
  build.host_counters = buffers_.host_counters.handle();
  build.counter_bytes = kCountersBytes;
  build.consumer_stages = VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
  build.consumer_access = VK_ACCESS_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_SHADER_READ_BIT;
  record_compute_build(cmd, build);
}

GpuTileLists::Counts GpuTileLists::read_counts() const {
  const std::span<const std::uint32_t> values = buffers_.host_counters.as<const std::uint32_t>();
  Counts counts;
  counts.tiles.assign(values.begin(), values.begin() + class_count_);
  counts.invalid_tiles = values[std::size_t{2} * kTileListMaxClasses];
  return counts;
}

}  // namespace tilelight
