#include "compute_lighting_passes.h"

#include "branch_set.h"
#include "descriptors.h"
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

// Mirrors uber/lighting.comp.
constexpr std::uint32_t kNaiveOptimisedId = 31;  // every feature: the full uber-shader
constexpr std::uint32_t kWorkgroupSize = 64;     // LIGHT_GROUP_SIZE
constexpr std::uint32_t kFullFrameSide = 8;      // FULL_FRAME_GROUP_SIDE
constexpr std::uint32_t kTileSizeConstant = 0;   // constant_id of TILE_SIZE
constexpr std::uint32_t kFullFrameConstant = 1;  // constant_id of FULL_FRAME
constexpr std::uint32_t kTaggedConstant = 2;     // TAGGED_GBUFFER (light_pass.glsl)
constexpr std::uint32_t kSamplesConstant = 8;    // LIGHT_GBUFFER_SAMPLES
constexpr std::uint32_t kTargetSet = 1;
constexpr std::uint32_t kTargetBinding = 0;     // light_target
constexpr std::uint32_t kTileListsBinding = 1;  // tile_lists.glsl's default
constexpr VkDeviceSize kDispatchRecordBytes = sizeof(VkDispatchIndirectCommand);
constexpr VkClearColorValue kUncoveredColour{{1.0f, 0.0f, 1.0f, 1.0f}};  // magenta, as the raster pass

const Scope kComputeWrite{VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT};
const Scope kTransferRead{VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT};

// Set `set` of the compute registry must be the other registry's: both bind the same set
// (LightingInterface's set 0; set 1 of the tile build and of the variant build).
void check_set_matches(const shadergen::Registry& compute, const shadergen::Registry& fragment, std::uint32_t set) {
  const auto compute0 = shadergen::vk::descriptor_set_layout_bindings(compute.pipeline_layout, set);
  const auto fragment0 = shadergen::vk::descriptor_set_layout_bindings(fragment.pipeline_layout, set);
  bool same = compute0.size() == fragment0.size();
  for (std::size_t i = 0; same && i < compute0.size(); ++i) {
    same = compute0[i].binding == fragment0[i].binding && compute0[i].descriptorType == fragment0[i].descriptorType &&
           compute0[i].descriptorCount == fragment0[i].descriptorCount;
  }
  if (!same) {
    throw Error("the compute light registry " + std::string(compute.name) + "'s set " + std::to_string(set) +
                " differs from " + std::string(fragment.name) +
                "'s (uber/include/lighting_params.glsl, uber/lighting.comp)");
  }
}

// The tile pass (not `full_frame`) reads the classified G-buffer, whose coverage flags exist with
// 2 or more samples; the baselines read the plain one.
// `specialization`: the values of the tile build's specialization features (empty for variants).
UniquePipeline create_light_pipeline(const Context& context, VkPipelineLayout layout,
                                     std::span<const std::uint32_t> spirv, const RenderTargets& targets,
                                     std::uint32_t tile_size, bool full_frame, const std::string& name,
                                     const shadergen::Specialization& specialization = {}) {
  const SpecConstants constants = SpecConstants{}
                                      .set(kTileSizeConstant, tile_size)
                                      .set(kFullFrameConstant, full_frame)
                                      .set(kTaggedConstant, !full_frame && targets.has_coverage_flags())
                                      .set(kSamplesConstant, static_cast<std::uint32_t>(targets.samples()))
                                      .add(shadergen::vulkan::specialization_info(specialization));
  return create_compute_pipeline(context, layout, spirv, constants, name);
}

void to_general(VkCommandBuffer cmd, const Image& target, Scope dst) {
  // The previous contents are not needed; earlier reads (the last readback) need only an
  // execution dependency.
  image_barrier(cmd, target.handle(), target.subresource_range(), VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                {VK_PIPELINE_STAGE_TRANSFER_BIT, 0}, dst);
}

void to_transfer_source(VkCommandBuffer cmd, const Image& target) {
  image_barrier(cmd, target.handle(), target.subresource_range(), VK_IMAGE_LAYOUT_GENERAL,
                VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, kComputeWrite, kTransferRead);
}

}  // namespace

std::uint32_t ComputeLightingPasses::tiles_per_workgroup(std::uint32_t tile_size) {
  return std::max(1u, kWorkgroupSize / (tile_size * tile_size));
}

ComputeLightingPasses::ComputeLightingPasses(const Context& context, const TileGrid& grid, const RenderTargets& targets,
                                             const LightingInterface& lighting, const LightClasses& classes,
                                             const BranchSet& branch, VkDescriptorPool pool, const Buffer& tile_lists,
                                             const FloorTarget* floor)
    : lighting_(&lighting), extent_(targets.extent()), branch_(&branch) {
  const shadergen::Registry& registry = compute_shaders_for(targets.samples());
  check_set_matches(registry, lighting.shaders(), 0);
  check_set_matches(*classes.shaders.registry, registry, 0);
  check_set_matches(*classes.shaders.registry, registry, kTargetSet);
  const std::vector<VkDescriptorSetLayoutBinding> set1 =
      shadergen::vk::descriptor_set_layout_bindings(registry.pipeline_layout, kTargetSet);
  if (set1.size() != 2) {
    throw Error("the compute light registry's set 1 has " + std::to_string(set1.size()) +
                " bindings; the runtime expects the light target and the tile lists of uber/lighting.comp");
  }
  target_set_layout_ = create_descriptor_set_layout(context, set1, "compute light set 1 layout");
  const std::vector<VkPushConstantRange> push = shadergen::vk::push_constant_ranges(registry);
  const std::array<VkDescriptorSetLayout, 2> sets{lighting.set0_layout(), target_set_layout_.get()};
  layout_ = create_pipeline_layout(context, sets, push, "compute light pipeline layout");

  auto target_set = [&](const Image& target, const std::string& name) {
    VkDescriptorSet set = allocate_descriptor_set(context, pool, target_set_layout_.get(), name);
    write_storage_image_descriptor(context, set, kTargetBinding, target.view());
    write_buffer_descriptor(context, set, kTileListsBinding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, tile_lists.handle());
    return set;
  };
  classified_set_ = target_set(targets.classified(), "compute light set 1 (classified)");
  naive_set_ = target_set(targets.naive(), "compute light set 1 (naive)");
  dynamic_set_ = target_set(targets.dynamic(), "compute light set 1 (dynamic)");

  tile_layout_ = layout_.get();
  if (branch.active()) {
    branch_layout_ = branch.pipeline_layout(context, sets, push, "compute light pipeline layout (branch block)");
    tile_layout_ = branch_layout_.get();
  }
  const std::uint32_t tile = grid.tile_size;
  const auto start = std::chrono::steady_clock::now();
  for (const LightPipelineSpec& p : classes.pipelines) {
    pipelines_.push_back(create_light_pipeline(context, tile_layout_, p.spirv, targets, tile, false,
                                               "compute lighting " + p.name, p.specialization));
  }
  tile_pipelines_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  for (const LightClass& c : classes.classes) class_pipelines_.push_back(c.pipeline);
  // The baselines below are the variant build's, whatever build the tile pass dispatches.
  if (registry.optimised.size() <= kNaiveOptimisedId) throw Error("the compute light registry has no optimised 31");
  naive_pipeline_ = create_light_pipeline(context, layout_.get(), registry.optimised[kNaiveOptimisedId].spirv, targets,
                                          tile, true, "compute lighting naive (optimised 31)");
  dynamic_pipeline_ =
      create_light_pipeline(context, layout_.get(), light_companions(registry).compute_lighting_dynamic.shader.spirv,
                            targets, tile, true, "compute lighting dynamic (per-pixel branches)");
  if (floor != nullptr) {
    floor_set_ = target_set(floor->image(), "compute light set 1 (floor)");
    floor_pipeline_ =
        create_light_pipeline(context, layout_.get(), light_companions(registry).compute_lighting_floor.shader.spirv,
                              targets, tile, true, "compute lighting floor (G-buffer read, no lighting)");
  }
}

void ComputeLightingPasses::bind(VkCommandBuffer cmd, VkDescriptorSet target_set, VkPipelineLayout layout) const {
  const std::array<VkDescriptorSet, 2> sets{lighting_->set0(), target_set};
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout, 0, 2, sets.data(), 0, nullptr);
}

void ComputeLightingPasses::record_prepare(VkCommandBuffer cmd, const RenderTargets& targets) const {
  const Image& target = targets.classified();
  to_general(cmd, target, {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT});
  const VkImageSubresourceRange range = target.subresource_range();
  vkCmdClearColorImage(cmd, target.handle(), VK_IMAGE_LAYOUT_GENERAL, &kUncoveredColour, 1, &range);
  image_barrier(cmd, target.handle(), range, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL,
                {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT}, kComputeWrite);
}

void ComputeLightingPasses::record_tiled(VkCommandBuffer cmd, const RenderTargets& targets,
                                         const Buffer& dispatches) const {
  // The lists and records are written after this command buffer was submitted (host patching)
  // or by an earlier compute pass (GPU-driven): make both kinds of write visible.
  memory_barrier(cmd,
                 {VK_PIPELINE_STAGE_HOST_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                  VK_ACCESS_HOST_WRITE_BIT | VK_ACCESS_SHADER_WRITE_BIT},
                 {VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                  VK_ACCESS_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_SHADER_READ_BIT});
  bind(cmd, classified_set_, tile_layout_);
  std::optional<std::uint32_t> bound;
  for (std::uint32_t id = 0; id < class_pipelines_.size(); ++id) {
    const std::optional<std::uint32_t> pipeline = class_pipelines_[id];
    if (!pipeline) continue;  // a pruned raw ID: the list build rejects it
    // One dispatch per class, a bind where its pipeline changes (classes of one optimised ID
    // share it in a branch build), and its branch values; a class without tiles dispatches
    // {0, 1, 1}: no work.
    if (pipeline != bound) vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines_[*pipeline].get());
    bound = pipeline;
    if (branch_->active()) branch_->bind(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, tile_layout_, id);
    vkCmdPushConstants(cmd, tile_layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(id), &id);
    vkCmdDispatchIndirect(cmd, dispatches.handle(), id * kDispatchRecordBytes);
  }
  to_transfer_source(cmd, targets.classified());
}

void ComputeLightingPasses::record_naive(VkCommandBuffer cmd, const RenderTargets& targets) const {
  record_full_frame(cmd, targets.naive(), naive_set_, naive_pipeline_.get());
}

void ComputeLightingPasses::record_dynamic(VkCommandBuffer cmd, const RenderTargets& targets) const {
  record_full_frame(cmd, targets.dynamic(), dynamic_set_, dynamic_pipeline_.get());
}

void ComputeLightingPasses::record_floor(VkCommandBuffer cmd, const FloorTarget& floor) const {
  record_full_frame(cmd, floor.image(), floor_set_, floor_pipeline_.get());
}

void ComputeLightingPasses::record_full_frame(VkCommandBuffer cmd, const Image& target, VkDescriptorSet target_set,
                                              VkPipeline pipeline) const {
  to_general(cmd, target, kComputeWrite);
  bind(cmd, target_set, layout_.get());
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
  const std::uint32_t no_class = 0;  // the push constant is unused by full-frame dispatches
  vkCmdPushConstants(cmd, layout_.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(no_class), &no_class);
  vkCmdDispatch(cmd, (extent_.width + kFullFrameSide - 1) / kFullFrameSide,
                (extent_.height + kFullFrameSide - 1) / kFullFrameSide, 1);
  to_transfer_source(cmd, target);
}

}  // namespace tilelight
