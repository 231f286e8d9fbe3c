#include "lighting_passes.h"

#include "branch_set.h"
#include "light_classes.h"
#include "pipelines.h"
#include "shader_registry.h"
#include "tilelight/vulkan/barriers.h"
#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <shadergen/vulkan.h>

#include <array>
#include <chrono>
#include <string>

namespace tilelight {
namespace {

constexpr std::uint32_t kNaiveOptimisedId = 31;  // every feature: the full uber-shader
constexpr std::uint32_t kTaggedConstant = 2;     // TAGGED_GBUFFER (light_pass.glsl)
constexpr VkDeviceSize kDrawRecordBytes = sizeof(VkDrawIndexedIndirectCommand);
constexpr std::uint32_t kCornerBinding = 0;  // tile.vert: the corner grid, per vertex
constexpr std::uint32_t kGridBinding = 1;    // tile_point.vert: the grid's shape, per instance

// `tile_pass`: the classified path's pass, which reads the classified G-buffer (coverage flags,
// with 2 or more samples); the baselines read the plain one.
// `specialization`: the values of the build's specialization features (empty for variants).
UniquePipeline create_light_pipeline(const Context& context, const RenderTargets& targets,
                                     const LightingInterface& lighting, VkPipelineLayout layout,
                                     std::span<const std::uint32_t> fragment,
                                     const shadergen::Specialization& specialization, TilePrimitive primitive,
                                     bool tile_pass, std::string name) {
  GraphicsPipelineDesc desc;
  desc.layout = layout;
  desc.render_pass = targets.light_pass();
  desc.fragment_spirv = fragment;
  desc.fragment_constants.set(kTaggedConstant, tile_pass && targets.has_coverage_flags());
  desc.fragment_constants.add(shadergen::vulkan::specialization_info(specialization));
  if (primitive == TilePrimitive::points) {
    // tile_point.vert computes each point from its index; binding 1 holds the grid's shape.
    desc.vertex_spirv = light_companions(lighting.shaders()).tile_point.shader.spirv;
    desc.topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST;
    desc.vertex_bindings = {{kGridBinding, 2 * sizeof(float), VK_VERTEX_INPUT_RATE_INSTANCE}};
    desc.vertex_attributes = {{0, kGridBinding, VK_FORMAT_R32G32_SFLOAT, 0}};
  } else {
    desc.vertex_spirv = light_companions(lighting.shaders()).tile.shader.spirv;
    desc.vertex_bindings = {{kCornerBinding, 2 * sizeof(float), VK_VERTEX_INPUT_RATE_VERTEX}};
    desc.vertex_attributes = {{0, kCornerBinding, VK_FORMAT_R32G32_SFLOAT, 0}};
  }
  desc.name = std::move(name) + " (" + std::string(to_string(primitive)) + ")";
  return create_graphics_pipeline(context, desc);
}

// The tile build's set 0 must be the lighting set the variant build's reflection made: the tile
// pass binds that set.
void check_set0_matches(const shadergen::Registry& tile, const shadergen::Registry& variant) {
  const auto tile0 = shadergen::vk::descriptor_set_layout_bindings(tile.pipeline_layout, 0);
  const auto variant0 = shadergen::vk::descriptor_set_layout_bindings(variant.pipeline_layout, 0);
  bool same = tile0.size() == variant0.size();
  for (std::size_t i = 0; same && i < tile0.size(); ++i) {
    same = tile0[i].binding == variant0[i].binding && tile0[i].descriptorType == variant0[i].descriptorType &&
           tile0[i].descriptorCount == variant0[i].descriptorCount;
  }
  if (!same) {
    throw Error("the light registry " + std::string(tile.name) + "'s set 0 differs from " + std::string(variant.name) +
                "'s (uber/include/lighting_params.glsl)");
  }
}

}  // namespace

LightingPasses::LightingPasses(const Context& context, const TileGrid& grid, const RenderTargets& targets,
                               const LightingInterface& lighting, const LightClasses& classes, const BranchSet& branch,
                               TilePrimitive primitive, bool floor)
    : lighting_(&lighting),
      branch_(&branch),
      extent_(targets.extent()),
      viewport_{grid.tiles_x * grid.tile_size, grid.tiles_y * grid.tile_size} {
  // Exact in float: a frame within the device's framebuffer limits is far below 2^24 tiles across.
  const std::array<float, 2> grid_shape{static_cast<float>(grid.tiles_x + 1), static_cast<float>(grid.tile_size)};
  grid_shape_ = Buffer(
      context, {sizeof(grid_shape), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, MemoryUse::HostUpload, "tile grid shape"});
  grid_shape_.write_values(std::span<const float>(grid_shape));
  const std::vector<float> corners = grid.corner_vertices();
  corners_ = Buffer(context, {corners.size() * sizeof(float), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, MemoryUse::HostUpload,
                              "tile corner grid"});
  corners_.write_values(std::span<const float>(corners));
  const std::array<std::uint32_t, 6> whole_frame{grid.vertex_index(0, 0),
                                                 grid.vertex_index(grid.tiles_x, 0),
                                                 grid.vertex_index(0, grid.tiles_y),
                                                 grid.vertex_index(grid.tiles_x, 0),
                                                 grid.vertex_index(grid.tiles_x, grid.tiles_y),
                                                 grid.vertex_index(0, grid.tiles_y)};
  full_screen_indices_ = Buffer(context, {sizeof(whole_frame), VK_BUFFER_USAGE_INDEX_BUFFER_BIT, MemoryUse::HostUpload,
                                          "full-screen pass indices"});
  full_screen_indices_.write_values(std::span<const std::uint32_t>(whole_frame));

  const shadergen::Registry& registry = lighting.shaders();
  check_set0_matches(*classes.shaders.registry, registry);
  tile_layout_ = lighting.lighting_layout();
  if (branch.active()) {
    const std::array<VkDescriptorSetLayout, 1> sets{lighting.set0_layout()};
    branch_layout_ = branch.pipeline_layout(context, sets, shadergen::vk::push_constant_ranges(registry),
                                            "lighting pipeline layout (branch block)");
    tile_layout_ = branch_layout_.get();
  }
  const auto start = std::chrono::steady_clock::now();
  for (const LightPipelineSpec& p : classes.pipelines) {
    pipelines_.push_back(create_light_pipeline(context, targets, lighting, tile_layout_, p.spirv, p.specialization,
                                               primitive, true, "lighting " + p.name));
  }
  tile_pipelines_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  for (const LightClass& c : classes.classes) class_pipelines_.push_back(c.pipeline);
  // The whole frame is not a square: two triangles, whose one diagonal costs little. The
  // baselines are the variant build's, whatever build the tile pass draws: the reference.
  const shadergen::Specialization none{};
  naive_pipeline_ = create_light_pipeline(context, targets, lighting, lighting.lighting_layout(),
                                          registry.optimised[kNaiveOptimisedId].spirv, none, TilePrimitive::triangles,
                                          false, "lighting naive (optimised 31)");
  dynamic_pipeline_ = create_light_pipeline(context, targets, lighting, lighting.lighting_layout(),
                                            light_companions(registry).lighting_dynamic.shader.spirv, none,
                                            TilePrimitive::triangles, false, "lighting dynamic (per-pixel branches)");
  if (floor) {
    floor_pipeline_ = create_light_pipeline(
        context, targets, lighting, lighting.lighting_layout(), light_companions(registry).lighting_floor.shader.spirv,
        none, TilePrimitive::triangles, false, "lighting floor (G-buffer read, no lighting)");
  }
}

void LightingPasses::begin(VkCommandBuffer cmd, const RenderTargets& targets, VkFramebuffer framebuffer,
                           VkPipelineLayout layout) const {
  // Magenta: a pixel the tiled pass failed to cover stands out, and fails the equivalence test.
  VkClearValue clear{};
  clear.color = {{1.0f, 0.0f, 1.0f, 1.0f}};
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = targets.light_pass();
  begin.framebuffer = framebuffer;
  begin.renderArea = {{0, 0}, extent_};
  begin.clearValueCount = 1;
  begin.pClearValues = &clear;
  vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
  // The viewport spans whole tiles, so a point's centre is inside it even for a partial tile at
  // the right or bottom edge (a point whose centre is outside the viewport is culled whole);
  // the scissor keeps drawing inside the frame. Pixels map 1:1 either way.
  const VkViewport viewport{0.0f, 0.0f, static_cast<float>(viewport_.width), static_cast<float>(viewport_.height),
                            0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, extent_};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  const VkDescriptorSet set = lighting_->set0();
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &set, 0, nullptr);
  const std::array<float, 2> inv_viewport{1.0f / static_cast<float>(viewport_.width),
                                          1.0f / static_cast<float>(viewport_.height)};
  vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(inv_viewport), inv_viewport.data());
  const std::array<VkBuffer, 2> vertex_buffers{corners_.handle(), grid_shape_.handle()};
  const std::array<VkDeviceSize, 2> offsets{0, 0};
  vkCmdBindVertexBuffers(cmd, kCornerBinding, 2, vertex_buffers.data(), offsets.data());
}

void LightingPasses::record_tiled(VkCommandBuffer cmd, const RenderTargets& targets, const Buffer& indices,
                                  const Buffer& draws) const {
  // The records are written after this command buffer was submitted (host patching) or by an
  // earlier compute pass (GPU-driven): make both kinds of write visible to the draw stages.
  memory_barrier(cmd,
                 {VK_PIPELINE_STAGE_HOST_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                  VK_ACCESS_HOST_WRITE_BIT | VK_ACCESS_SHADER_WRITE_BIT},
                 {VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_VERTEX_INPUT_BIT,
                  VK_ACCESS_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_INDEX_READ_BIT});
  begin(cmd, targets, targets.classified_framebuffer(), tile_layout_);
  vkCmdBindIndexBuffer(cmd, indices.handle(), 0, VK_INDEX_TYPE_UINT32);
  std::optional<std::uint32_t> bound;
  for (std::uint32_t id = 0; id < class_pipelines_.size(); ++id) {
    const std::optional<std::uint32_t> pipeline = class_pipelines_[id];
    if (!pipeline) continue;  // a pruned raw ID: the index build rejects it
    // One draw per class, a bind where its pipeline changes (classes of one optimised ID share
    // it in a branch build), and its branch values; a class without tiles has indexCount 0.
    if (pipeline != bound) vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_[*pipeline].get());
    bound = pipeline;
    if (branch_->active()) branch_->bind(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, tile_layout_, id);
    vkCmdDrawIndexedIndirect(cmd, draws.handle(), id * kDrawRecordBytes, 1,
                             static_cast<std::uint32_t>(kDrawRecordBytes));
  }
  vkCmdEndRenderPass(cmd);
}

void LightingPasses::record_naive(VkCommandBuffer cmd, const RenderTargets& targets) const {
  record_full_screen(cmd, targets, targets.naive_framebuffer(), naive_pipeline_.get());
}

void LightingPasses::record_dynamic(VkCommandBuffer cmd, const RenderTargets& targets) const {
  record_full_screen(cmd, targets, targets.dynamic_framebuffer(), dynamic_pipeline_.get());
}

void LightingPasses::record_floor(VkCommandBuffer cmd, const RenderTargets& targets, const FloorTarget& floor) const {
  record_full_screen(cmd, targets, floor.framebuffer(), floor_pipeline_.get());
}

void LightingPasses::record_full_screen(VkCommandBuffer cmd, const RenderTargets& targets, VkFramebuffer framebuffer,
                                        VkPipeline pipeline) const {
  begin(cmd, targets, framebuffer, lighting_->lighting_layout());
  vkCmdBindIndexBuffer(cmd, full_screen_indices_.handle(), 0, VK_INDEX_TYPE_UINT32);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
  vkCmdDrawIndexed(cmd, 6, 1, 0, 0, 0);
  vkCmdEndRenderPass(cmd);
}

}  // namespace tilelight
