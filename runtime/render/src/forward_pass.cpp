#include "forward_pass.h"

#include "descriptors.h"
#include "light_target_layout.h"
#include "light_target_pass.h"
#include "local_light_block.h"
#include "pipelines.h"
#include "reflected_layout.h"
#include "scene_vertex_input.h"
#include "shader_registry.h"
#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <shadergen/vulkan.h>

#include <cstring>
#include <string>

namespace tilelight {
namespace {

// lighting_params.glsl's set 0 and forward_params.glsl's block.
constexpr std::uint32_t kParamsBinding = 0;
constexpr std::uint32_t kFirstGBufferBinding = 1;  // RT0..RT3 at 1..4
constexpr std::uint32_t kShadowMapBinding = 5;
constexpr std::uint32_t kForwardBinding = 8;
constexpr std::uint32_t kBaseColourSet = 2;
constexpr std::uint32_t kLocalLightsBit = 1;   // permutations/forward.json: LOCAL_LIGHTS, bit 0
constexpr std::uint32_t kLocalShadowsBit = 2;  // LOCAL_SHADOWS, bit 1

// forward_params.glsl's ForwardParams (std140).
struct ForwardParamsBlock {
  glm::mat4 view_proj;
  glm::vec4 ambient_sky;
  glm::vec4 ambient_ground;
};

// forward_params.glsl's ForwardDraw: the light count, then the indices four to a uvec4.
struct DrawConstants {
  glm::uvec4 light_count;
  std::array<std::uint32_t, kForwardMaxLights> lights;
};
constexpr std::uint32_t kDrawConstantBytes = sizeof(DrawConstants);
static_assert(kDrawConstantBytes == 48);

// The image view set 0's binding `binding` reads (lighting_params.glsl's numbering).
VkImageView set0_view(const RenderTargets& targets, std::uint32_t binding) {
  switch (binding) {
    case kFirstGBufferBinding: return targets.rt0().view();
    case kFirstGBufferBinding + 1: return targets.rt1().view();
    case kFirstGBufferBinding + 2: return targets.rt2().view();
    case kFirstGBufferBinding + 3: return targets.rt3().view();
    case kShadowMapBinding: return targets.shadow_map().view();
    default: break;
  }
  throw Error("forward.json's set 0 has binding " + std::to_string(binding) +
              ", which the forward pass does not bind (lighting_params.glsl, forward_params.glsl)");
}

template <typename T>
Buffer upload_values(const Context& context, std::span<const T> data, VkBufferUsageFlags usage, std::string name) {
  Buffer buffer(context, {std::max<VkDeviceSize>(data.size_bytes(), 4), usage, MemoryUse::HostUpload, std::move(name)});
  buffer.write_values(data);
  return buffer;
}

}  // namespace

ForwardPass::ForwardPass(const Context& context, const Scene& scene, const Camera& camera, const RenderTargets& targets,
                         const LightingParamsBlock& params, const ScenePasses& scene_passes, VkDescriptorPool pool,
                         const LocalLightShadows& shadows)
    : shaders_(&forward_shaders_for(targets.samples())),
      scene_passes_(&scene_passes),
      draws_(plan_forward_draws(scene, camera.position)),
      params_block_(params) {
  if (draws_.empty()) return;  // nothing blended: no buffers, sets or pipelines
  upload(context, scene, scene_passes.textures(),
         make_scene_params(scene, camera, targets.extent().width, targets.extent().height), shadows);
  render_pass_ = create_light_target_pass(context, targets.gbuffer_depth_format(), "forward pass");
  depth_ = Image(
      context, {targets.extent(), targets.gbuffer_depth_format(), VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                VK_SAMPLE_COUNT_1_BIT, VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT, "forward pass: depth"});
  create_framebuffers(context, targets);
  create_sets(context, targets, pool, scene_passes.textures(), shadows);
  create_pipelines(context);
}

std::uint32_t ForwardPass::raw_id_of(const ForwardDraw& draw) const {
  if (draw.light_count == 0) return 0;
  for (std::uint32_t i = 0; i < draw.light_count; ++i) {
    if (light_has_map_[draw.lights[i]]) return kLocalLightsBit | kLocalShadowsBit;
  }
  return kLocalLightsBit;
}

void ForwardPass::upload(const Context& context, const Scene& scene, const SceneTextures& textures,
                         const SceneParamsBlock& scene_params, const LocalLightShadows& shadows) {
  meshes_.resize(scene.meshes.size());
  std::vector<Instance> instances;
  for (const ForwardDraw& draw : draws_) {
    instances.push_back(scene.instances[draw.instance]);
    MeshBuffers& buffers = meshes_[draw.mesh];
    const Mesh& mesh = scene.meshes[draw.mesh];
    buffers.base_colour = textures.set_of(mesh.base_colour_texture);
    buffers.culled = !mesh.double_sided;
  }
  instances_ = upload_values<Instance>(context, instances, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                                       "blended instances (back to front)");
  const ForwardParamsBlock block{scene_params.view_proj, scene_params.ambient_sky, scene_params.ambient_ground};
  forward_params_ = upload_values<ForwardParamsBlock>(context, std::span(&block, 1), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                                      "forward parameters");
  params_ = upload_values<LightingParamsBlock>(context, std::span(&params_block_, 1),
                                               VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, "forward lighting parameters");
  // At least one block: set 1 binds the buffer even where no instance reads a light.
  std::vector<LocalLightBlock> blocks = make_local_light_blocks(scene.local_lights);
  shadows.place_faces_in(blocks);
  for (const LocalLightBlock& light : blocks) light_has_map_.push_back(light.kind.w != 0);
  if (blocks.empty()) blocks.push_back(LocalLightBlock{});
  lights_ =
      upload_values<LocalLightBlock>(context, blocks, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "forward pass: local lights");
}

void ForwardPass::create_sets(const Context& context, const RenderTargets& targets, VkDescriptorPool pool,
                              const SceneTextures& textures, const LocalLightShadows& shadows) {
  const shadergen::Registry& registry = *shaders_;
  layout_ = create_light_target_layout(context, registry, textures.set_layout(), kDrawConstantBytes, "forward",
                                       "forward_params.glsl");

  sampler_ = Sampler(context, {.name = "forward pass: G-buffer and shadow map (texelFetch)"});
  set0_ = allocate_descriptor_set(context, pool, layout_.set0_layout.get(), "forward set 0");
  for (const VkDescriptorSetLayoutBinding& b : layout_.set0) {
    if (b.binding == kParamsBinding) {
      write_buffer_descriptor(context, set0_, b.binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, params_.handle());
    } else if (b.binding == kForwardBinding) {
      write_buffer_descriptor(context, set0_, b.binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, forward_params_.handle());
    } else {
      write_image_descriptor(context, set0_, b.binding, sampler_.handle(), set0_view(targets, b.binding),
                             VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    }
  }
  set1_ = allocate_descriptor_set(context, pool, layout_.set1_layout.get(), "forward set 1");
  write_buffer_descriptor(context, set1_, 0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, lights_.handle());
  if (shadows.has_maps()) {
    set3_ =
        shadows.allocate_set(context, pool, layout_.set3_layout.get(), sampler_.handle(), "forward set 3 (shadows)");
  }
}

void ForwardPass::create_framebuffers(const Context& context, const RenderTargets& targets) {
  framebuffers_ = create_light_target_framebuffers(context, render_pass_.get(), targets, &depth_, "forward pass");
}

void ForwardPass::create_pipelines(const Context& context) {
  const shadergen::Registry& registry = *shaders_;
  const GraphicsPipelineDesc depth = depth_from_gbuffer_desc(
      layout_.pipeline.get(), render_pass_.get(), forward_companions(registry).full_screen.shader.spirv,
      forward_companions(registry).depth.shader.spirv, "forward pass: depth from the G-buffer");
  depth_pipeline_ = create_graphics_pipeline(context, depth);

  for (const ForwardDraw& draw : draws_) {
    const std::uint32_t raw_id = raw_id_of(draw);
    const bool culled = meshes_[draw.mesh].culled;
    UniquePipeline& pipeline = pipelines_[raw_id][culled ? 1 : 0];
    if (pipeline) continue;
    GraphicsPipelineDesc desc;
    desc.layout = layout_.pipeline.get();
    desc.render_pass = render_pass_.get();
    desc.vertex_spirv = forward_companions(registry).vertex.shader.spirv;
    desc.fragment_spirv = registry.raw[raw_id].spirv;
    desc.vertex_bindings = scene_vertex_bindings();
    desc.vertex_attributes = scene_vertex_attributes();  // forward.vert reads every one
    desc.depth_test = true;
    desc.depth_write = false;  // blended surfaces hide nothing behind them
    desc.depth_compare = VK_COMPARE_OP_LESS;
    desc.cull_mode = culled ? VK_CULL_MODE_BACK_BIT : VK_CULL_MODE_NONE;
    desc.alpha_blend = true;
    desc.name = std::string("forward raw ") + std::to_string(raw_id) + (culled ? ", single-sided" : "");
    pipeline = create_graphics_pipeline(context, desc);
  }
}

void ForwardPass::record(VkCommandBuffer cmd, const RenderTargets& targets, LocalLightTarget target) const {
  if (draws_.empty()) return;
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = render_pass_.get();
  begin.framebuffer = framebuffers_[static_cast<std::size_t>(target)].get();
  begin.renderArea = {{0, 0}, targets.extent()};
  std::array<VkClearValue, 2> clears{};
  clears[1].depthStencil = {1.0f, 0};
  begin.clearValueCount = static_cast<std::uint32_t>(clears.size());
  begin.pClearValues = clears.data();
  vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
  set_viewport_and_scissor(cmd, targets.extent());
  const std::array<VkDescriptorSet, 2> sets{set0_, set1_};
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_.pipeline.get(), 0, 2, sets.data(), 0, nullptr);
  if (set3_ != VK_NULL_HANDLE) {
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_.pipeline.get(), LocalLightShadows::kSet, 1,
                            &set3_, 0, nullptr);
  }
  // First the depth the geometry is tested against, then the geometry, in the same subpass.
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, depth_pipeline_.get());
  vkCmdDraw(cmd, 3, 1, 0, 0);
  for (std::uint32_t i = 0; i < draws_.size(); ++i) {
    const ForwardDraw& draw = draws_[i];
    const MeshBuffers& mesh = meshes_[draw.mesh];
    const std::uint32_t raw_id = raw_id_of(draw);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_[raw_id][mesh.culled ? 1 : 0].get());
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_.pipeline.get(), kBaseColourSet, 1,
                            &mesh.base_colour, 0, nullptr);
    DrawConstants constants{glm::uvec4(draw.light_count, 0, 0, 0), draw.lights};
    std::array<std::byte, kDrawConstantBytes> bytes{};
    std::memcpy(bytes.data(), &constants, bytes.size());
    vkCmdPushConstants(cmd, layout_.pipeline.get(), layout_.push_stages, 0, kDrawConstantBytes, bytes.data());
    const std::uint32_t index_count = scene_passes_->bind_mesh(cmd, draw.mesh, instances_.handle());
    vkCmdDrawIndexed(cmd, index_count, 1, 0, 0, i);
  }
  vkCmdEndRenderPass(cmd);
}

}  // namespace tilelight
