#include "local_light_shadows.h"

#include "descriptors.h"
#include "pipelines.h"
#include "reflected_layout.h"
#include "scene_passes.h"
#include "scene_vertex_input.h"
#include "shader_registry.h"
#include "tilelight/scene/batch_culling.h"
#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>

namespace tilelight {
namespace {

constexpr VkFormat kAtlasFormat = VK_FORMAT_D32_SFLOAT;  // kShadowDepthBytes
constexpr std::uint32_t kTextureSet = 1;                 // shadow_mask.frag's base colour texture
// The casters' rasteriser bias (as the sun's, DepthBias): a constant and a multiple of each
// triangle's depth slope, with the receiver's normal offset against acne.
constexpr DepthBias kCasterDepthBias{2.0f, 2.0f};

std::uint32_t max_atlas_texels(const Context& context) {
  const DeviceLimits& limits = context.limits();
  return std::min({limits.max_image_dimension_2d, limits.max_framebuffer_width, limits.max_framebuffer_height});
}

}  // namespace

LocalLightShadows::LocalLightShadows(const Context& context, const Scene& scene, const ScenePasses& scene_passes,
                                     VkDescriptorSetLayout texture_set_layout, const LocalShadowOptions& options)
    : options_(options), scene_passes_(&scene_passes) {
  if (options.face_size <= 2 * kFaceBorderTexels || options.face_size > max_atlas_texels(context)) {
    throw Error("local-light shadow faces of " + std::to_string(options.face_size) + " texels: the device renders " +
                std::to_string(2 * kFaceBorderTexels + 1) + " to " + std::to_string(max_atlas_texels(context)));
  }
  plan_ = plan_local_shadows(scene.local_lights, options.enabled, options.face_size, options.cap_bytes,
                             max_atlas_texels(context));
  if (!has_maps()) return;
  faces_blocks_ = place_shadow_faces(scene.local_lights, plan_);
  const std::vector<WorldBox> bounds = batch_bounds(scene);
  for (const LocalShadowFaceBlock& face : faces_blocks_)
    face_batches_.push_back(select_batches(bounds, face.view_proj).drawn);
  masked_ = scene_passes.draws_casters(true);
  unmasked_ = scene_passes.draws_casters(false);

  atlas_ = Image(context, {{plan_.columns * plan_.face_size, plan_.rows * plan_.face_size},
                           kAtlasFormat,
                           VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                           VK_SAMPLE_COUNT_1_BIT,
                           VK_IMAGE_ASPECT_DEPTH_BIT,
                           "local-light shadow atlas"});
  faces_ = Buffer(context, {faces_blocks_.size() * sizeof(LocalShadowFaceBlock), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                            MemoryUse::HostUpload, "local-light shadow faces"});
  faces_.write_values(std::span<const LocalShadowFaceBlock>(faces_blocks_));
  create_render_pass(context);
  create_pipelines(context, texture_set_layout);
}

// One depth attachment, the atlas, cleared (1: nothing in front) and stored; left for the
// local-light shaders to sample.
void LocalLightShadows::create_render_pass(const Context& context) {
  VkAttachmentDescription depth{};
  depth.format = kAtlasFormat;
  depth.samples = VK_SAMPLE_COUNT_1_BIT;
  depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  depth.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  depth.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  depth.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  depth.finalLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  const VkAttachmentReference reference{0, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.pDepthStencilAttachment = &reference;
  constexpr VkPipelineStageFlags kTests =
      VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
  // In: after the previous frame's local lights read the atlas. Out: before they read it again.
  const std::array<VkSubpassDependency, 2> dependencies{{
      {VK_SUBPASS_EXTERNAL, 0, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, kTests, 0,
       VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, 0},
      {0, VK_SUBPASS_EXTERNAL, kTests, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
       VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT, 0},
  }};
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = 1;
  info.pAttachments = &depth;
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = static_cast<std::uint32_t>(dependencies.size());
  info.pDependencies = dependencies.data();
  VkRenderPass pass = VK_NULL_HANDLE;
  check(vkCreateRenderPass(context.device(), &info, nullptr, &pass), "vkCreateRenderPass", "local-light shadows");
  render_pass_ = UniqueRenderPass(pass, {context.device()});
  context.name_object(pass, "local-light shadows");

  const VkImageView view = atlas_.view();
  VkFramebufferCreateInfo fb{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  fb.renderPass = pass;
  fb.attachmentCount = 1;
  fb.pAttachments = &view;
  fb.width = atlas_.extent().width;
  fb.height = atlas_.extent().height;
  fb.layers = 1;
  VkFramebuffer framebuffer = VK_NULL_HANDLE;
  check(vkCreateFramebuffer(context.device(), &fb, nullptr, &framebuffer), "vkCreateFramebuffer",
        "local-light shadow atlas");
  framebuffer_ = UniqueFramebuffer(framebuffer, {context.device()});
  context.name_object(framebuffer, "local-light shadow atlas");
}

// Both sides of every mesh cast (no culling), as in the sun's map: a single-sided leaf still
// shades. The layout: set 0 unused, set 1 the scene texture's (a masked caster's base colour),
// the face's transform pushed.
void LocalLightShadows::create_pipelines(const Context& context, VkDescriptorSetLayout texture_set_layout) {
  // Either build of the domain: the casters read no G-buffer.
  const shadergen::Registry& registry = local_light_shaders_for(VK_SAMPLE_COUNT_1_BIT);
  const std::array<const shadergen::Reflection*, 3> shaders{
      &local_light_companions(registry).shadow_caster.shader.reflection,
      &local_light_companions(registry).shadow_caster_masked.shader.reflection,
      &local_light_companions(registry).shadow_caster_mask.shader.reflection};
  const std::vector<VkDescriptorSetLayoutBinding> set0 = merged_set_bindings(shaders, 0, "local shadow casters' set 0");
  if (!set0.empty()) throw Error("the local shadow casters' shaders bind set 0, which the runtime leaves empty");
  const std::vector<VkDescriptorSetLayoutBinding> set1 =
      merged_set_bindings(shaders, kTextureSet, "local shadow set 1");
  const std::array<VkDescriptorType, 1> texture{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER};
  check_bindings(set1, texture, "local shadow casters' set 1 (the base colour texture)");
  const std::vector<VkPushConstantRange> push = merged_push_constant_ranges(shaders, VK_SHADER_STAGE_VERTEX_BIT);
  if (push_constant_bytes(push) != sizeof(glm::mat4)) {
    throw Error("local_shadow_caster.vert pushes " + std::to_string(push_constant_bytes(push)) +
                " bytes; the runtime pushes a face's transform (64)");
  }
  empty_set_layout_ = create_descriptor_set_layout(context, {}, "local shadow casters' empty set 0");
  const std::array<VkDescriptorSetLayout, 2> sets{empty_set_layout_.get(), texture_set_layout};
  layout_ = create_pipeline_layout(context, sets, push, "local shadow casters' layout");
  for (const bool masked : {false, true}) {
    if (!(masked ? masked_ : unmasked_)) continue;
    GraphicsPipelineDesc desc;
    desc.layout = layout_.get();
    desc.render_pass = render_pass_.get();
    const LocalLightCompanions& c = local_light_companions(registry);
    desc.vertex_spirv = (masked ? c.shadow_caster_masked : c.shadow_caster).shader.spirv;
    if (masked) desc.fragment_spirv = c.shadow_caster_mask.shader.spirv;
    desc.vertex_bindings = scene_vertex_bindings();  // ScenePasses' buffers
    desc.vertex_attributes = shadow_caster_attributes(masked);
    desc.color_attachments = 0;
    desc.depth_test = true;
    desc.depth_write = true;
    desc.depth_bias = kCasterDepthBias;
    desc.name = masked ? "local-light shadow casters (alpha-masked)" : "local-light shadow casters";
    (masked ? masked_pipeline_ : opaque_) = create_graphics_pipeline(context, desc);
  }
}

void LocalLightShadows::record(VkCommandBuffer cmd) {
  if (!renders_this_frame()) return;
  VkClearValue clear{};
  clear.depthStencil = {1.0f, 0};
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = render_pass_.get();
  begin.framebuffer = framebuffer_.get();
  begin.renderArea = {{0, 0}, atlas_.extent()};
  begin.clearValueCount = 1;
  begin.pClearValues = &clear;
  vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
  for (std::size_t f = 0; f < faces_blocks_.size(); ++f) {
    const LocalShadowFaceBlock& face = faces_blocks_[f];
    const float size = static_cast<float>(face.rect.z);
    const VkViewport viewport{static_cast<float>(face.rect.x), static_cast<float>(face.rect.y), size, size, 0.0f, 1.0f};
    const VkRect2D scissor{{static_cast<std::int32_t>(face.rect.x), static_cast<std::int32_t>(face.rect.y)},
                           {face.rect.z, face.rect.z}};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    for (const bool masked : {false, true}) {
      const VkPipeline pipeline = masked ? masked_pipeline_.get() : opaque_.get();
      if (pipeline == VK_NULL_HANDLE) continue;
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
      vkCmdPushConstants(cmd, layout_.get(), VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(glm::mat4), &face.view_proj);
      scene_passes_->draw_casters(cmd, masked, face_batches_[f], layout_.get(), kTextureSet);
    }
  }
  vkCmdEndRenderPass(cmd);
  rendered_ = true;
}

void LocalLightShadows::place_faces_in(std::vector<LocalLightBlock>& blocks) const {
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const bool shadowed = plan_.first_face[i] != kNoShadow;
    blocks[i].kind.z = shadowed ? plan_.first_face[i] : 0u;
    blocks[i].kind.w = plan_.face_count[i];
  }
}

std::vector<VkDescriptorSetLayoutBinding> LocalLightShadows::set_bindings(const shadergen::Registry& registry,
                                                                          std::string_view pass) {
  const std::string what = std::string(pass) + " set 3";
  std::vector<VkDescriptorSetLayoutBinding> bindings = merged_set_bindings({registry.pipeline_layout}, kSet, what);
  const std::array<VkDescriptorType, 2> types{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                                              VK_DESCRIPTOR_TYPE_STORAGE_BUFFER};
  check_bindings(bindings, types, what + " (the shadow atlas and its faces)");
  return bindings;
}

VkDescriptorSet LocalLightShadows::allocate_set(const Context& context, VkDescriptorPool pool,
                                                VkDescriptorSetLayout layout, VkSampler sampler,
                                                std::string_view name) const {
  const VkDescriptorSet set = allocate_descriptor_set(context, pool, layout, name);
  write_image_descriptor(context, set, 0, sampler, atlas_view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  write_buffer_descriptor(context, set, 1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, faces_buffer());
  return set;
}

}  // namespace tilelight
