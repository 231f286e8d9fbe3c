#include "tile_classification.h"

#include "descriptors.h"
#include "pipelines.h"
#include "shader_registry.h"
#include "tilelight/render/tile_renderer.h"
#include "tilelight/vulkan/barriers.h"
#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <split_second_shaders.h>

#include <array>

namespace tilelight {
namespace {

// The raw bit layout comes from the generated registry (the domain spec), not from the shader.
SpecConstants classification_constants(std::uint32_t tile_size, std::uint32_t samples) {
  namespace bit = split_second::raw_bit;
  SpecConstants spec;
  spec.set(0, tile_size)
      .set(1, bit::SHADOW_SOLID.value())
      .set(2, bit::SHADOW_SOFT.value())
      .set(3, bit::SHADOW_FADE.value())
      .set(4, bit::LIGHT_SCATTERING.value())
      .set(5, bit::MSAA_EDGE.value())
      .set(6, bit::SKY.value())
      .set(7, bit::SUN_LIGHT.value())
      .set(8, samples);
  return spec;
}

}  // namespace

TileClassification::TileClassification(const Context& context, const TileGrid& grid, const RenderTargets& targets,
                                       const LightingInterface& lighting, VkDescriptorPool pool)
    : lighting_(&lighting), grid_(grid) {
  ids_ = Buffer(context, {grid.id_bytes(), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                          MemoryUse::DeviceLocal, "tile IDs (blocked)"});
  host_ids_ = Buffer(
      context, {grid.id_bytes(), VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::HostReadback, "tile IDs (host copy)"});
  ids_set_ = allocate_descriptor_set(context, pool, lighting.storage_set_layout(), "tile ID output set");
  write_buffer_descriptor(context, ids_set_, 0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, ids_.handle());
  classify_ = create_compute_pipeline(
      context, lighting.compute_layout(), light_companions(lighting.shaders()).classify_tiles.shader.spirv,
      classification_constants(grid.tile_size, static_cast<std::uint32_t>(targets.samples())), "tile classification");
}

void TileClassification::record(VkCommandBuffer cmd) const {
  const std::array<VkDescriptorSet, 2> sets{lighting_->set0(), ids_set_};
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, classify_.get());
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, lighting_->compute_layout(), 0,
                          static_cast<std::uint32_t>(sets.size()), sets.data(), 0, nullptr);
  const std::array<std::uint32_t, 4> push{grid_.tiles_x, grid_.tiles_y, grid_.blocks_x, grid_.blocks_y};
  vkCmdPushConstants(cmd, lighting_->compute_layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push), push.data());
  // One invocation per block row, 64 per work group (classify_tiles.comp).
  constexpr std::uint32_t kRowsPerGroup = 64;
  const std::uint32_t block_rows = grid_.blocks_x * grid_.blocks_y * 4;
  vkCmdDispatch(cmd, (block_rows + kRowsPerGroup - 1) / kRowsPerGroup, 1, 1);

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

}  // namespace tilelight
