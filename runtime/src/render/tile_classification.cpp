#include "tile_classification.h"

#include "companion_shaders.h"
#include "descriptors.h"
#include "tilelight/barriers.h"
#include "tilelight/context.h"
#include "tilelight/error.h"
#include "tilelight/pipelines.h"

#include <split_second_shaders.h>

#include <array>

namespace tilelight {
namespace {

// The raw bit layout comes from the generated registry (the domain spec), not from the shader.
// classify_tiles.comp's two passes (its CLASSIFY_PASS constant).
enum class ClassifyPass : std::uint32_t { tiles = 0, deferred_shadows = 1 };

// One record of classify_tiles.comp's DeferredShadow list (std430: 4 x 16 bytes), and the
// list's header (the indirect dispatch of pass 1 and the record count).
constexpr VkDeviceSize kDeferredRecordBytes = 64;
constexpr VkDeviceSize kDeferredHeaderBytes = 16;

SpecConstants classification_constants(std::uint32_t tile_size, std::uint32_t samples, ClassifyPass pass) {
  namespace bit = split_second::raw_bit;
  SpecConstants spec;
  spec.set(0, tile_size)
      .set(8, static_cast<std::uint32_t>(pass))
      .set(9, samples)
      .set(1, bit::SHADOW_SOLID)
      .set(2, bit::SHADOW_SOFT)
      .set(3, bit::SHADOW_FADE)
      .set(4, bit::LIGHT_SCATTERING)
      .set(5, bit::MSAA_EDGE)
      .set(6, bit::SKY)
      .set(7, bit::SUN_LIGHT);
  return spec;
}

}  // namespace

TileClassification::TileClassification(const Context& context, const TileGrid& grid, std::uint32_t samples,
                                       const LightingInterface& lighting, VkDescriptorPool pool)
    : lighting_(&lighting), grid_(grid) {
  ids_ = Buffer(context, {grid.id_bytes(),
                          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                          MemoryUse::DeviceLocal, "tile IDs (blocked)"});
  host_ids_ = Buffer(context, {grid.id_bytes(), VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::HostReadback,
                               "tile IDs (host copy)"});
  // Room for every tile: each is appended at most once.
  const VkDeviceSize tiles = static_cast<VkDeviceSize>(grid.tiles_x) * grid.tiles_y;
  deferred_ = Buffer(context, {kDeferredHeaderBytes + tiles * kDeferredRecordBytes,
                               VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                                   VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                               MemoryUse::DeviceLocal, "deferred shadow decisions"});
  ids_set_ = allocate_descriptor_set(context, pool, lighting.storage_set_layout(), "tile ID output set");
  write_buffer_descriptor(context, ids_set_, 0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, ids_.handle());
  deferred_set_ = allocate_descriptor_set(context, pool, lighting.storage_set_layout(), "deferred shadow set");
  write_buffer_descriptor(context, deferred_set_, 0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, deferred_.handle());

  const std::array<VkDescriptorSetLayout, 3> sets{lighting.set0_layout(), lighting.storage_set_layout(),
                                                  lighting.storage_set_layout()};
  classify_layout_ = create_pipeline_layout(context, sets, std::span(&LightingInterface::kComputePush, 1),
                                            "tile classification layout");
  const std::span<const std::uint32_t> spirv = companion_spirv("classify_tiles");
  classify_ = create_compute_pipeline(context, classify_layout_.get(), spirv,
                                      classification_constants(grid.tile_size, samples, ClassifyPass::tiles),
                                      "tile classification");
  settle_ = create_compute_pipeline(context, classify_layout_.get(), spirv,
                                    classification_constants(grid.tile_size, samples, ClassifyPass::deferred_shadows),
                                    "tile classification (deferred shadows)");

}

void TileClassification::record(VkCommandBuffer cmd) const {
  // Empty deferred list: no records, pass 1 dispatched as (0, 1, 1) work groups until pass 0
  // appends.
  const std::array<std::uint32_t, 4> empty_list{0, 1, 1, 0};
  vkCmdUpdateBuffer(cmd, deferred_.handle(), 0, sizeof(empty_list), empty_list.data());
  buffer_barrier(cmd, deferred_.handle(), {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT},
                 {VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT});

  const std::array<VkDescriptorSet, 3> sets{lighting_->set0(), ids_set_, deferred_set_};
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, classify_layout_.get(), 0,
                          static_cast<std::uint32_t>(sets.size()), sets.data(), 0, nullptr);
  const std::array<std::uint32_t, 4> push{grid_.tiles_x, grid_.tiles_y, grid_.blocks_x, grid_.blocks_y};
  vkCmdPushConstants(cmd, classify_layout_.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push), push.data());
  // Pass 0: one invocation per block row, 64 per work group (classify_tiles.comp).
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, classify_.get());
  constexpr std::uint32_t kRowsPerGroup = 64;
  const std::uint32_t block_rows = grid_.blocks_x * grid_.blocks_y * 4;
  vkCmdDispatch(cmd, (block_rows + kRowsPerGroup - 1) / kRowsPerGroup, 1, 1);

  // Pass 1: one invocation per deferred tile, as many work groups as pass 0 counted; it ORs
  // shadow bits into the IDs pass 0 wrote.
  buffer_barrier(cmd, deferred_.handle(), {VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT},
                 {VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                  VK_ACCESS_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_SHADER_READ_BIT});
  buffer_barrier(cmd, ids_.handle(), {VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT},
                 {VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT});
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, settle_.get());
  vkCmdDispatchIndirect(cmd, deferred_.handle(), 0);

  buffer_barrier(cmd, ids_.handle(), {VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT},
                 {VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                  VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_SHADER_READ_BIT});
  const VkBufferCopy copy{0, 0, grid_.id_bytes()};
  vkCmdCopyBuffer(cmd, ids_.handle(), host_ids_.handle(), 1, &copy);
  buffer_barrier(cmd, host_ids_.handle(), {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT},
                 {VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT});
}

std::span<const std::uint8_t> TileClassification::host_ids() const {
  const std::span<std::byte> bytes = host_ids_.bytes();
  return {reinterpret_cast<const std::uint8_t*>(bytes.data()), grid_.id_bytes()};
}

void TileClassification::enable_gbuffer_dump(const Context& context, VkDescriptorPool pool,
                                             std::uint32_t samples) {
  if (dump_pipeline_) return;
  // Large (64 bytes per sample): created only for the tests and tools that ask for it.
  const VkDeviceSize values = static_cast<VkDeviceSize>(grid_.width) * grid_.height * samples * 16;
  dump_ = Buffer(context, {values * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::HostReadback,
                           "G-buffer dump"});
  dump_set_ = allocate_descriptor_set(context, pool, lighting_->storage_set_layout(), "G-buffer dump set");
  write_buffer_descriptor(context, dump_set_, 0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, dump_.handle());
  dump_pipeline_ = create_compute_pipeline(context, lighting_->compute_layout(), companion_spirv("gbuffer_dump"), {},
                                           "G-buffer dump");
}

void TileClassification::record_gbuffer_dump(VkCommandBuffer cmd) const {
  if (!dump_pipeline_) throw Error("the G-buffer dump was not enabled");
  const std::array<VkDescriptorSet, 2> sets{lighting_->set0(), dump_set_};
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, dump_pipeline_.get());
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, lighting_->compute_layout(), 0, 2, sets.data(), 0,
                          nullptr);
  vkCmdDispatch(cmd, (grid_.width + 7) / 8, (grid_.height + 7) / 8, 1);
  buffer_barrier(cmd, dump_.handle(), {VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT},
                 {VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT});
}

std::span<const float> TileClassification::host_gbuffer_dump() const {
  return dump_.as<const float>();
}

}  // namespace tilelight
