#include "scene_passes.h"

#include "descriptors.h"
#include "pipelines.h"
#include "reflected_layout.h"
#include "scene_vertex_input.h"
#include "shader_registry.h"
#include "tilelight/scene/uniform_blocks.h"
#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <split_second_shaders.h>

#include <algorithm>
#include <array>
#include <string>

namespace tilelight {
namespace {

// The sun shadow map's depth bias, against shadow acne: the stored occluder depths are pushed
// away from the sun by a constant and by a multiple of each triangle's depth slope. The slope
// term matters on curved receivers near the terminator (the street camera's sphere), where
// the 8 PCF taps reach texels whose own triangles slope steeply away; too little of it there
// shows as speckled self-shadow and makes sunlit tiles SOFT_SHADOW.
constexpr DepthBias kShadowMapDepthBias{2.0f, 8.0f};

template <typename T>
Buffer upload_buffer(const Context& context, std::span<const T> data, VkBufferUsageFlags usage, std::string name) {
  Buffer buffer(context, {std::max<VkDeviceSize>(data.size_bytes(), 4), usage, MemoryUse::HostUpload, std::move(name)});
  buffer.write_values(data);
  return buffer;
}

// The attributes of scene_vertex_attributes() whose locations `wanted` accepts: a pipeline gets only those
// its vertex shader reads (unused attributes are a validation performance warning).
template <typename Wanted>
std::vector<VkVertexInputAttributeDescription> scene_attributes_where(Wanted wanted) {
  std::vector<VkVertexInputAttributeDescription> kept;
  for (const VkVertexInputAttributeDescription& a : scene_vertex_attributes()) {
    if (wanted(a.location)) kept.push_back(a);
  }
  return kept;
}

// The batch kinds (ScenePasses::kBatchKinds): masked ones read location 9 (the alpha mask), culled
// ones are single-sided.
bool masked_kind(std::size_t kind) { return kind >= 2; }
bool culled_kind(std::size_t kind) { return kind % 2 == 1; }
std::size_t batch_kind(const Mesh& mesh) { return (mesh.alpha_mask ? 2 : 0) + (mesh.double_sided ? 0 : 1); }

// Every shader drawn with the scene's pipeline layout: the shadow map's and both G-buffers'.
std::array<const shadergen::Reflection*, 12> scene_shaders(const shadergen::Registry& shaders) {
  const LightCompanions& c = light_companions(shaders);
  const auto of = [](const shadergen::CompanionShader& shader) { return &shader.shader.reflection; };
  return {
      of(c.scene),         of(c.shadow),      of(c.gbuffer),      of(c.gbuffer_flagged), of(c.sky_vertex),
      of(c.sky),           of(c.sky_flagged), of(c.scene_masked), of(c.gbuffer_masked),  of(c.gbuffer_masked_flagged),
      of(c.shadow_masked), of(c.shadow_mask)};
}

// Set `set` of the scene's pipeline layout, as the scene shaders' reflection declares it;
// `expected` is what ScenePasses or SceneTextures binds there (checked).
std::vector<VkDescriptorSetLayoutBinding> scene_set_bindings(const shadergen::Registry& shaders, std::uint32_t set,
                                                             VkDescriptorType expected, std::string_view what) {
  std::vector<VkDescriptorSetLayoutBinding> bindings = merged_set_bindings(scene_shaders(shaders), set, what);
  check_bindings(bindings, std::span(&expected, 1), what);
  return bindings;
}

std::vector<VkDescriptorSetLayoutBinding> scene_params_bindings(const RenderTargets& targets) {
  return scene_set_bindings(shaders_for(targets.samples()), 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                            "scene set 0 (scene parameters)");
}

std::vector<VkDescriptorSetLayoutBinding> base_colour_bindings(const RenderTargets& targets) {
  return scene_set_bindings(shaders_for(targets.samples()), 1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                            "scene set 1 (base colour texture)");
}

}  // namespace

ScenePasses::ScenePasses(const Context& context, const Scene& scene, const Camera& camera, const RenderTargets& targets,
                         VkDescriptorPool pool, const CommandPool& upload_pool, bool cull)
    : textures_(context, upload_pool, scene.textures, base_colour_bindings(targets)), batches_(scene.batches) {
  for (const Mesh& mesh : scene.meshes) {
    MeshBuffers buffers;
    buffers.vertices = upload_buffer<MeshVertex>(context, mesh.vertices, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                                                 "mesh " + mesh.name + " vertices");
    buffers.indices = upload_buffer<std::uint32_t>(context, mesh.indices, VK_BUFFER_USAGE_INDEX_BUFFER_BIT,
                                                   "mesh " + mesh.name + " indices");
    buffers.index_count = static_cast<std::uint32_t>(mesh.indices.size());
    buffers.base_colour = textures_.set_of(mesh.base_colour_texture);
    buffers.kind = batch_kind(mesh);
    buffers.blend = mesh.blend;
    meshes_.push_back(std::move(buffers));
  }
  for (const MeshBatch& batch : batches_) {
    if (!meshes_[batch.mesh].blend) kind_drawn_[meshes_[batch.mesh].kind] = true;
  }
  instances_ = upload_buffer<Instance>(context, scene.instances, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, "scene instances");
  const SceneParamsBlock block = make_scene_params(scene, camera, targets.extent().width, targets.extent().height);
  params_ = upload_buffer<SceneParamsBlock>(context, std::span(&block, 1), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                            "scene parameters");
  select_drawn_batches(scene, block, cull);

  set_layout_ = create_descriptor_set_layout(context, scene_params_bindings(targets), "scene set layout");
  const VkDescriptorSetLayout set_layouts[] = {set_layout_.get(), textures_.set_layout()};
  const shadergen::Registry& shaders = shaders_for(targets.samples());
  const std::vector<VkPushConstantRange> push =
      merged_push_constant_ranges(scene_shaders(shaders), VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT);
  layout_ = create_pipeline_layout(context, set_layouts, push, "scene pipeline layout");
  set_ = allocate_descriptor_set(context, pool, set_layout_.get(), "scene descriptor set");
  write_buffer_descriptor(context, set_, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, params_.handle());

  plain_ = create_gbuffer_pipelines(context, shaders, targets, false);
  if (targets.has_coverage_flags()) {
    if (!context.features().post_depth_coverage) {
      throw Error("the classified G-buffer's coverage flags need VK_EXT_post_depth_coverage, which " +
                  context.device_name() + " lacks (--msaa 1 needs no flags)");
    }
    flagged_ = create_gbuffer_pipelines(context, shaders, targets, true);
  }

  create_shadow_pipelines(context, shaders, targets);
}

// Both sides of every mesh cast shadows (no culling): a single-sided leaf still shades.
void ScenePasses::create_shadow_pipelines(const Context& context, const shadergen::Registry& shaders,
                                          const RenderTargets& targets) {
  for (const bool masked : {false, true}) {
    if (!kind_drawn_[masked ? 2 : 0] && !kind_drawn_[masked ? 3 : 1]) continue;
    GraphicsPipelineDesc shadow;
    shadow.layout = layout_.get();
    shadow.render_pass = targets.shadow_pass();
    const LightCompanions& c = light_companions(shaders);
    shadow.vertex_spirv = (masked ? c.shadow_masked : c.shadow).shader.spirv;
    if (masked) shadow.fragment_spirv = c.shadow_mask.shader.spirv;
    shadow.vertex_bindings = scene_vertex_bindings();
    shadow.vertex_attributes = shadow_caster_attributes(masked);
    shadow.color_attachments = 0;
    shadow.depth_test = true;
    shadow.depth_write = true;
    shadow.depth_bias = kShadowMapDepthBias;
    shadow.name = masked ? "sun shadow map (alpha-masked)" : "sun shadow map";
    shadow_pipelines_[masked ? 1 : 0] = create_graphics_pipeline(context, shadow);
  }
}

ScenePasses::GBufferPipelines ScenePasses::create_gbuffer_pipelines(const Context& context,
                                                                    const shadergen::Registry& shaders,
                                                                    const RenderTargets& targets,
                                                                    bool with_flags) const {
  const std::string pass = with_flags ? " (classified)" : " (plain)";
  const LightCompanions& c = light_companions(shaders);
  GBufferPipelines pipelines;
  for (std::size_t kind = 0; kind < kBatchKinds; ++kind) {
    if (!kind_drawn_[kind]) continue;
    const bool masked = masked_kind(kind);
    const std::string what = std::string(masked ? ", alpha-masked" : "") + (culled_kind(kind) ? ", single-sided" : "");
    GraphicsPipelineDesc materials =
        targets.gbuffer_pipeline_desc(layout_.get(), "G-buffer materials" + what + pass, with_flags);
    materials.vertex_spirv = (masked ? c.scene_masked : c.scene).shader.spirv;
    const shadergen::CompanionShader& fragment = masked ? (with_flags ? c.gbuffer_masked_flagged : c.gbuffer_masked)
                                                        : (with_flags ? c.gbuffer_flagged : c.gbuffer);
    materials.fragment_spirv = fragment.shader.spirv;
    materials.vertex_bindings = scene_vertex_bindings();
    materials.vertex_attributes =
        scene_attributes_where([masked](std::uint32_t location) { return masked || location != 9; });
    materials.depth_write = true;
    materials.stencil = gbuffer_stencil_marking();  // needs lighting (the sky leaves 0)
    materials.cull_mode = culled_kind(kind) ? VK_CULL_MODE_BACK_BIT : VK_CULL_MODE_NONE;
    pipelines.materials[kind] = create_graphics_pipeline(context, materials);
  }

  GraphicsPipelineDesc sky = targets.gbuffer_pipeline_desc(layout_.get(), "G-buffer sky" + pass, with_flags);
  sky.vertex_spirv = c.sky_vertex.shader.spirv;
  sky.fragment_spirv = (with_flags ? c.sky_flagged : c.sky).shader.spirv;
  sky.depth_compare = VK_COMPARE_OP_LESS_OR_EQUAL;
  pipelines.sky = create_graphics_pipeline(context, sky);
  return pipelines;
}

// The camera and the sun are fixed per renderer, so each pass's batches are chosen once.
void ScenePasses::select_drawn_batches(const Scene& scene, const SceneParamsBlock& block, bool cull) {
  if (!cull) {
    gbuffer_batches_.drawn.assign(scene.batches.size(), true);
    shadow_batches_.drawn.assign(scene.batches.size(), true);
    return;
  }
  const std::vector<WorldBox> bounds = batch_bounds(scene);
  gbuffer_batches_ = select_batches(bounds, block.view_proj);
  shadow_batches_ = select_batches(bounds, block.sun_view_proj);
}

void ScenePasses::draw_batches(VkCommandBuffer cmd, bool textured, std::size_t kind,
                               const BatchSelection& selection) const {
  for (std::size_t i = 0; i < batches_.size(); ++i) {
    const MeshBatch& batch = batches_[i];
    if (!selection.drawn[i]) continue;
    const MeshBuffers& mesh = meshes_[batch.mesh];
    if (mesh.kind != kind || mesh.blend) continue;  // blended meshes: the forward pass's alone
    if (textured) {
      vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_.get(), 1, 1, &mesh.base_colour, 0, nullptr);
    }
    const std::uint32_t index_count = bind_mesh(cmd, batch.mesh, instances_.handle());
    vkCmdDrawIndexed(cmd, index_count, batch.instance_count, 0, 0, batch.first_instance);
  }
}

std::uint32_t ScenePasses::bind_mesh(VkCommandBuffer cmd, std::uint32_t mesh, VkBuffer instances) const {
  const MeshBuffers& buffers = meshes_[mesh];
  const std::array<VkBuffer, 2> vertex_buffers{buffers.vertices.handle(), instances};
  const std::array<VkDeviceSize, 2> offsets{0, 0};
  vkCmdBindVertexBuffers(cmd, 0, static_cast<std::uint32_t>(vertex_buffers.size()), vertex_buffers.data(),
                         offsets.data());
  vkCmdBindIndexBuffer(cmd, buffers.indices.handle(), 0, VK_INDEX_TYPE_UINT32);
  return buffers.index_count;
}

void ScenePasses::draw_casters(VkCommandBuffer cmd, bool masked, const std::vector<bool>& drawn,
                               VkPipelineLayout layout, std::uint32_t texture_set) const {
  for (std::size_t i = 0; i < batches_.size(); ++i) {
    const MeshBatch& batch = batches_[i];
    const MeshBuffers& mesh = meshes_[batch.mesh];
    // Blended meshes cast no shadow, local or the sun's (docs/local-lights.md, forward pass).
    if (!drawn[i] || mesh.blend || masked_kind(mesh.kind) != masked) continue;
    if (masked) {
      vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, texture_set, 1, &mesh.base_colour, 0,
                              nullptr);
    }
    const std::uint32_t index_count = bind_mesh(cmd, batch.mesh, instances_.handle());
    vkCmdDrawIndexed(cmd, index_count, batch.instance_count, 0, 0, batch.first_instance);
  }
}

void ScenePasses::record_shadow_map(VkCommandBuffer cmd, const RenderTargets& targets) const {
  VkClearValue clear{};
  clear.depthStencil = {1.0f, 0};
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = targets.shadow_pass();
  begin.framebuffer = targets.shadow_framebuffer();
  begin.renderArea = {{0, 0}, targets.shadow_extent()};
  begin.clearValueCount = 1;
  begin.pClearValues = &clear;
  vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
  set_viewport_and_scissor(cmd, targets.shadow_extent());
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_.get(), 0, 1, &set_, 0, nullptr);
  for (std::size_t kind = 0; kind < kBatchKinds; ++kind) {
    if (!kind_drawn_[kind]) continue;
    const bool masked = masked_kind(kind);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, shadow_pipelines_[masked ? 1 : 0].get());
    draw_batches(cmd, masked, kind, shadow_batches_);
  }
  vkCmdEndRenderPass(cmd);
}

void ScenePasses::record_gbuffer(VkCommandBuffer cmd, const RenderTargets& targets) const {
  record_gbuffer_with(cmd, targets, targets.has_coverage_flags() ? flagged_ : plain_, true);
}

void ScenePasses::record_gbuffer_plain(VkCommandBuffer cmd, const RenderTargets& targets) const {
  record_gbuffer_with(cmd, targets, plain_, false);
}

void ScenePasses::record_gbuffer_with(VkCommandBuffer cmd, const RenderTargets& targets,
                                      const GBufferPipelines& pipelines, bool with_flags) const {
  targets.begin_gbuffer_pass(cmd, with_flags);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_.get(), 0, 1, &set_, 0, nullptr);
  for (std::size_t kind = 0; kind < kBatchKinds; ++kind) {
    if (!kind_drawn_[kind]) continue;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines.materials[kind].get());
    draw_batches(cmd, true, kind, gbuffer_batches_);
  }
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines.sky.get());
  vkCmdDraw(cmd, 3, 1, 0, 0);
  vkCmdEndRenderPass(cmd);
}

}  // namespace tilelight
