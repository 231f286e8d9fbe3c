#include "local_light_passes.h"

#include "descriptors.h"
#include "light_target_layout.h"
#include "light_target_pass.h"
#include "local_light_block.h"
#include "local_light_permutation.h"
#include "pipelines.h"
#include "reflected_layout.h"
#include "shader_registry.h"
#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <shadergen/vulkan.h>

#include <array>
#include <cstring>
#include <string>

namespace tilelight {
namespace {

// lighting_params.glsl's set 0, as local_light.frag reads it.
constexpr std::uint32_t kParamsBinding = 0;
constexpr std::uint32_t kFirstGBufferBinding = 1;  // RT0..RT3 at 1..4
constexpr std::uint32_t kShadowMapBinding = 5;
constexpr std::uint32_t kCoverageFlagsBinding = 6;
constexpr std::uint32_t kStencilBinding = 7;  // local_light_resolve.frag: the G-buffer's stencil
constexpr std::uint32_t kGlobeSet = 2;
constexpr std::uint32_t kTaggedConstant = 2;  // TAGGED_GBUFFER (local_light.frag)

// The push constants of every draw (local_light_draw.glsl): 68 bytes, as the reflection says.
struct DrawConstants {
  glm::mat4 view_proj;
  std::uint32_t light_index;
};
constexpr std::uint32_t kDrawConstantBytes = 68;

// The image view set 0's binding `binding` reads, as lighting_params.glsl (and
// local_light_resolve.frag, the stencil) declare it.
VkImageView set0_view(const RenderTargets& targets, std::uint32_t binding) {
  switch (binding) {
    case kFirstGBufferBinding: return targets.rt0().view();
    case kFirstGBufferBinding + 1: return targets.rt1().view();
    case kFirstGBufferBinding + 2: return targets.rt2().view();
    case kFirstGBufferBinding + 3: return targets.rt3().view();
    case kShadowMapBinding: return targets.shadow_map().view();
    case kCoverageFlagsBinding:
      if (targets.has_coverage_flags()) return targets.coverage_flags().view();
      break;
    case kStencilBinding: return targets.gbuffer_stencil_view();
    default: break;
  }
  throw Error("local_lights.json's set 0 has binding " + std::to_string(binding) +
              ", which lighting_params.glsl does not declare for this G-buffer");
}

// What every local-light pipeline shares: the layout and render pass, the light's permutation
// with or without the coverage flags (`tagged`), blended ONE + ONE into the light target.
// `vertex`: the domain's companion drawing it (full_screen or volume).
GraphicsPipelineDesc light_pipeline_desc(const shadergen::Registry& registry, VkPipelineLayout layout,
                                         VkRenderPass render_pass, const shadergen::CompanionShader& vertex,
                                         std::uint32_t raw_id, bool tagged) {
  GraphicsPipelineDesc desc;
  desc.layout = layout;
  desc.render_pass = render_pass;
  desc.vertex_spirv = vertex.shader.spirv;
  desc.fragment_spirv = registry.raw[raw_id].spirv;
  desc.fragment_constants.set(kTaggedConstant, tagged ? 1u : 0u);
  desc.additive_blend = true;
  desc.name = "local light " + std::string(vertex.name) + " raw " + std::to_string(raw_id) +
              (tagged ? " (tagged G-buffer)" : "");
  return desc;
}

}  // namespace

LocalLightPasses::LocalLightPasses(const Context& context, const Scene& scene, const RenderTargets& targets,
                                   const LightingParamsBlock& params, const SceneTextures& textures,
                                   VkDescriptorPool pool, LocalLightPass pass, const LocalLightShadows& shadows)
    : shaders_(&local_light_shaders_for(targets.samples())), params_block_(params), pass_(pass) {
  if (scene.local_lights.empty()) return;  // nothing to draw: no sets, no pipelines
  const bool multisampled = targets.samples() != VK_SAMPLE_COUNT_1_BIT;
  view_proj_ = glm::inverse(params.inv_view_proj);
  const bool depth_clamp = context.features().depth_clamp;
  for (std::uint32_t i = 0; i < scene.local_lights.size(); ++i) {
    const LocalLight& light = scene.local_lights[i];
    const bool shadowed = shadows.plan().first_face[i] != kNoShadow;
    Draw draw{i, local_light_raw_id(light, multisampled, shadowed), VK_NULL_HANDLE, volume_of(light),
              depth_clamp || !may_cross_far_plane(light, view_proj_)};
    if (light.extras.globe_texture) {
      if (*light.extras.globe_texture >= scene.textures.size()) {
        throw Error("local light " + std::to_string(i) + ": globe texture " +
                    std::to_string(*light.extras.globe_texture) + " is not one of the scene's " +
                    std::to_string(scene.textures.size()) + " textures");
      }
      draw.globe = textures.set_of(light.extras.globe_texture);
    }
    draws_.push_back(draw);
  }
  const bool volumes = pass == LocalLightPass::volumes;
  render_pass_ = create_light_target_pass(context, volumes ? targets.gbuffer_depth_format() : VK_FORMAT_UNDEFINED,
                                          "local-light pass");
  if (volumes) {
    resolved_depth_ =
        Image(context, {targets.extent(), targets.gbuffer_depth_format(), VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                        VK_SAMPLE_COUNT_1_BIT, VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT,
                        "local lights: resolved depth and stencil"});
  }
  create_framebuffers(context, targets);
  create_sets(context, targets, pool, textures, scene.local_lights, shadows);
  if (volumes) {
    create_volume_meshes(context);
    create_volume_pipelines(context, targets, depth_clamp);
  } else {
    create_full_screen_pipelines(context, targets);
  }
}

void LocalLightPasses::create_volume_meshes(const Context& context) {
  meshes_ = make_volume_meshes();
  volume_vertices_ = Buffer(context, {meshes_.vertices.size() * sizeof(glm::vec3), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                                      MemoryUse::HostUpload, "light volume meshes (vertices)"});
  volume_vertices_.write_values(std::span<const glm::vec3>(meshes_.vertices));
  volume_indices_ = Buffer(context, {meshes_.indices.size() * sizeof(std::uint32_t), VK_BUFFER_USAGE_INDEX_BUFFER_BIT,
                                     MemoryUse::HostUpload, "light volume meshes (indices)"});
  volume_indices_.write_values(std::span<const std::uint32_t>(meshes_.indices));
}

void LocalLightPasses::create_volume_pipelines(const Context& context, const RenderTargets& targets, bool depth_clamp) {
  const shadergen::Registry& registry = *shaders_;
  GraphicsPipelineDesc resolve = depth_from_gbuffer_desc(
      layout_.pipeline.get(), render_pass_.get(), local_light_companions(registry).full_screen.shader.spirv,
      local_light_companions(registry).resolve.shader.spirv, "local lights: resolve depth and stencil");
  resolve.stencil = gbuffer_stencil_marking();  // REPLACE with kStencilLit where not discarded
  resolve_ = create_graphics_pipeline(context, resolve);

  // Shade where the stencil is marked and the volume's back face is at or behind the surface.
  VkStencilOpState lit{};
  lit.failOp = lit.passOp = lit.depthFailOp = VK_STENCIL_OP_KEEP;
  lit.compareOp = VK_COMPARE_OP_EQUAL;
  lit.compareMask = 0xFF;
  lit.reference = kStencilLit;
  auto create = [&](std::uint32_t raw_id, bool tagged, bool depth_tested) {
    GraphicsPipelineDesc desc = light_pipeline_desc(registry, layout_.pipeline.get(), render_pass_.get(),
                                                    local_light_companions(registry).volume, raw_id, tagged);
    desc.vertex_bindings = {{0, sizeof(glm::vec3), VK_VERTEX_INPUT_RATE_VERTEX}};
    desc.vertex_attributes = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0}};
    desc.cull_mode = VK_CULL_MODE_FRONT_BIT;  // inverted winding: the camera may be inside
    desc.depth_test = depth_tested;
    desc.depth_compare = VK_COMPARE_OP_GREATER_OR_EQUAL;
    desc.depth_clamp = depth_clamp;
    desc.stencil = lit;
    if (!depth_tested) desc.name += " (no depth test)";
    return create_graphics_pipeline(context, desc);
  };
  for (const Draw& draw : draws_) {
    const std::uint32_t key = draw.raw_id * 2 + (draw.depth_tested ? 1 : 0);
    if (volume_.contains(key)) continue;
    PipelinePair& pair = volume_[key];
    pair.plain = create(draw.raw_id, false, draw.depth_tested);
    if (targets.has_coverage_flags()) pair.tagged = create(draw.raw_id, true, draw.depth_tested);
  }
}

void LocalLightPasses::create_sets(const Context& context, const RenderTargets& targets, VkDescriptorPool pool,
                                   const SceneTextures& textures, const std::vector<LocalLight>& lights,
                                   const LocalLightShadows& shadows) {
  const shadergen::Registry& registry = *shaders_;
  layout_ = create_light_target_layout(context, registry, textures.set_layout(), kDrawConstantBytes, "local-light",
                                       "local_light_draw.glsl");

  params_ = Buffer(context, {sizeof(LightingParamsBlock), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, MemoryUse::HostUpload,
                             "local-light lighting parameters"});
  params_.write_values(std::span<const LightingParamsBlock>(&params_block_, 1));
  sampler_ = Sampler(context, {.name = "local lights: G-buffer (texelFetch)"});
  set0_ = allocate_descriptor_set(context, pool, layout_.set0_layout.get(), "local-light set 0");
  for (const VkDescriptorSetLayoutBinding& b : layout_.set0) {
    if (b.binding == kParamsBinding) {
      write_buffer_descriptor(context, set0_, kParamsBinding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, params_.handle());
    } else {
      write_image_descriptor(context, set0_, b.binding, sampler_.handle(), set0_view(targets, b.binding),
                             VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    }
  }

  std::vector<LocalLightBlock> blocks = make_local_light_blocks(lights);
  shadows.place_faces_in(blocks);
  lights_ = Buffer(context, {blocks.size() * sizeof(LocalLightBlock), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                             MemoryUse::HostUpload, "local lights"});
  lights_.write_values(std::span<const LocalLightBlock>(blocks));
  set1_ = allocate_descriptor_set(context, pool, layout_.set1_layout.get(), "local-light set 1");
  write_buffer_descriptor(context, set1_, 0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, lights_.handle());
  if (shadows.has_maps()) {
    set3_ = shadows.allocate_set(context, pool, layout_.set3_layout.get(), sampler_.handle(),
                                 "local-light set 3 (shadows)");
  }
}

void LocalLightPasses::create_full_screen_pipelines(const Context& context, const RenderTargets& targets) {
  const shadergen::Registry& registry = *shaders_;
  auto create = [&](std::uint32_t raw_id, bool tagged) {
    return create_graphics_pipeline(context,
                                    light_pipeline_desc(registry, layout_.pipeline.get(), render_pass_.get(),
                                                        local_light_companions(registry).full_screen, raw_id, tagged));
  };
  for (const Draw& draw : draws_) {
    if (full_screen_.contains(draw.raw_id)) continue;
    PipelinePair& pair = full_screen_[draw.raw_id];
    pair.plain = create(draw.raw_id, false);
    if (targets.has_coverage_flags()) pair.tagged = create(draw.raw_id, true);
  }
}

std::uint32_t LocalLightPasses::pipeline_count() const {
  std::uint32_t count = 0;
  for (const auto& [id, pair] : full_screen_) count += (pair.plain ? 1 : 0) + (pair.tagged ? 1 : 0);
  for (const auto& [id, pair] : volume_) count += (pair.plain ? 1 : 0) + (pair.tagged ? 1 : 0);
  return count + (resolve_ ? 1 : 0);
}

void LocalLightPasses::create_framebuffers(const Context& context, const RenderTargets& targets) {
  framebuffers_ =
      create_light_target_framebuffers(context, render_pass_.get(), targets,
                                       pass_ == LocalLightPass::volumes ? &resolved_depth_ : nullptr, "local lights");
}

void LocalLightPasses::bind(VkCommandBuffer cmd, const RenderTargets& targets, LocalLightTarget target) const {
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = render_pass_.get();
  begin.framebuffer = framebuffers_[static_cast<std::size_t>(target)].get();
  begin.renderArea = {{0, 0}, targets.extent()};
  std::array<VkClearValue, 2> clears{};
  clears[1].depthStencil = {1.0f, 0};  // no surface, no lighting: what the resolve leaves for sky
  begin.clearValueCount = pass_ == LocalLightPass::volumes ? 2 : 0;
  begin.pClearValues = clears.data();
  vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
  set_viewport_and_scissor(cmd, targets.extent());
  const std::array<VkDescriptorSet, 2> sets{set0_, set1_};
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_.pipeline.get(), 0, 2, sets.data(), 0, nullptr);
  if (set3_ != VK_NULL_HANDLE) {
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_.pipeline.get(), LocalLightShadows::kSet, 1,
                            &set3_, 0, nullptr);
  }
}

void LocalLightPasses::record(VkCommandBuffer cmd, const RenderTargets& targets, LocalLightTarget target,
                              bool tagged_gbuffer) const {
  if (draws_.empty()) return;
  if (pass_ == LocalLightPass::volumes) {
    record_volumes(cmd, targets, target, tagged_gbuffer);
  } else {
    record_full_screen(cmd, targets, target, tagged_gbuffer);
  }
}

void LocalLightPasses::push_draw(VkCommandBuffer cmd, const Draw& draw) const {
  if (draw.globe != VK_NULL_HANDLE) {
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_.pipeline.get(), kGlobeSet, 1, &draw.globe, 0,
                            nullptr);
  }
  const DrawConstants constants{view_proj_, draw.light};
  std::array<std::byte, kDrawConstantBytes> bytes{};
  std::memcpy(bytes.data(), &constants, bytes.size());
  vkCmdPushConstants(cmd, layout_.pipeline.get(), layout_.push_stages, 0, kDrawConstantBytes, bytes.data());
}

void LocalLightPasses::record_volumes(VkCommandBuffer cmd, const RenderTargets& targets, LocalLightTarget target,
                                      bool tagged_gbuffer) const {
  bind(cmd, targets, target);
  // First the depth and stencil the volumes are tested against (depth and stencil only)...
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, resolve_.get());
  vkCmdDraw(cmd, 3, 1, 0, 0);
  // ... then each light's volume, in the same subpass: the tests see the resolve's writes.
  const VkDeviceSize offset = 0;
  const VkBuffer vertices = volume_vertices_.handle();
  vkCmdBindVertexBuffers(cmd, 0, 1, &vertices, &offset);
  vkCmdBindIndexBuffer(cmd, volume_indices_.handle(), 0, VK_INDEX_TYPE_UINT32);
  const bool tagged = tagged_gbuffer && targets.has_coverage_flags();
  for (const Draw& draw : draws_) {
    const PipelinePair& pair = volume_.at(draw.raw_id * 2 + (draw.depth_tested ? 1 : 0));
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, tagged ? pair.tagged.get() : pair.plain.get());
    push_draw(cmd, draw);
    const VolumeMesh& mesh = meshes_.meshes[static_cast<std::uint32_t>(draw.volume)];
    vkCmdDrawIndexed(cmd, mesh.index_count, 1, mesh.first_index, 0, 0);
  }
  vkCmdEndRenderPass(cmd);
}

void LocalLightPasses::record_full_screen(VkCommandBuffer cmd, const RenderTargets& targets, LocalLightTarget target,
                                          bool tagged_gbuffer) const {
  bind(cmd, targets, target);
  const bool tagged = tagged_gbuffer && targets.has_coverage_flags();
  for (const Draw& draw : draws_) {
    const PipelinePair& pair = full_screen_.at(draw.raw_id);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, tagged ? pair.tagged.get() : pair.plain.get());
    push_draw(cmd, draw);
    vkCmdDraw(cmd, 3, 1, 0, 0);
  }
  vkCmdEndRenderPass(cmd);
}

}  // namespace tilelight
