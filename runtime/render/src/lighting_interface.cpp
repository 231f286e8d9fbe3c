#include "lighting_interface.h"

#include "descriptors.h"
#include "pipelines.h"
#include "shader_registry.h"
#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <algorithm>
#include <array>
#include <string>

namespace tilelight {
namespace {

// Binding numbers of lighting_params.glsl; the registry's reflection must agree (checked).
constexpr std::uint32_t kParamsBinding = 0;
constexpr std::array<std::uint32_t, 5> kImageBindings{1, 2, 3, 4, 5};
constexpr std::uint32_t kFragmentTagsBinding = 6;  // classification only, multisampled G-buffer

// Set 0 of the light pass (the registry's merged layout) plus what the classifier alone reads
// from it (the fragment tags), from the classifier's own reflection.
std::vector<VkDescriptorSetLayoutBinding> set0_bindings(const shadergen::Registry& registry) {
  std::vector<VkDescriptorSetLayoutBinding> bindings = layout_bindings_for_set(registry.pipeline_layout, 0);
  const shadergen::Permutation& classifier = companion_shader(registry, "classify_tiles");
  for (const VkDescriptorSetLayoutBinding& b : layout_bindings_for_set(classifier.reflection.bindings, 0)) {
    const bool known = std::any_of(bindings.begin(), bindings.end(),
                                   [&](const VkDescriptorSetLayoutBinding& have) { return have.binding == b.binding; });
    if (!known) bindings.push_back(b);
  }
  return bindings;
}

}  // namespace

LightingInterface::LightingInterface(const Context& context, const LightingParamsBlock& params,
                                     const RenderTargets& targets, VkDescriptorPool pool)
    : shaders_(&shaders_for(targets.samples())), params_block_(params) {
  const shadergen::Registry& registry = *shaders_;
  params_ = Buffer(context, {sizeof(LightingParamsBlock), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, MemoryUse::HostUpload,
                             "lighting parameters"});
  params_.write_values(std::span<const LightingParamsBlock>(&params_block_, 1));
  sampler_ = Sampler(context, {.name = "G-buffer and shadow map (texelFetch and textureGather)"});

  // Every stage that could read set 0: the merged layout names the fragment stage; the
  // compute passes share the same set, so widen the stage mask.
  std::vector<VkDescriptorSetLayoutBinding> bindings = set0_bindings(registry);
  const std::size_t expected = 1 + kImageBindings.size() + (targets.has_fragment_tags() ? 1 : 0);
  if (bindings.size() != expected) {
    throw Error("the shader registry's set 0 has " + std::to_string(bindings.size()) +
                " bindings; the runtime expects the " + std::to_string(expected) + " of lighting_params.glsl");
  }
  for (VkDescriptorSetLayoutBinding& b : bindings) b.stageFlags |= VK_SHADER_STAGE_COMPUTE_BIT;
  set0_layout_ = create_descriptor_set_layout(context, bindings, "lighting set 0 layout");

  const VkDescriptorSetLayoutBinding storage{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT,
                                             nullptr};
  storage_set_layout_ = create_descriptor_set_layout(context, std::span(&storage, 1), "compute output set layout");

  std::vector<VkPushConstantRange> push;
  for (const shadergen::PushConstantRange& range : registry.push_constants) {
    push.push_back({range.stages, 0, range.size});
  }
  const std::array<VkDescriptorSetLayout, 1> lighting_sets{set0_layout_.get()};
  lighting_layout_ = create_pipeline_layout(context, lighting_sets, push, "lighting pipeline layout");
  const std::array<VkDescriptorSetLayout, 2> compute_sets{set0_layout_.get(), storage_set_layout_.get()};
  const VkPushConstantRange compute_push{VK_SHADER_STAGE_COMPUTE_BIT, 0, 32};
  compute_layout_ =
      create_pipeline_layout(context, compute_sets, std::span(&compute_push, 1), "classification pipeline layout");

  set0_ = allocate_descriptor_set(context, pool, set0_layout_.get(), "lighting set 0");
  write_buffer_descriptor(context, set0_, kParamsBinding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, params_.handle());
  const std::array<const Image*, 5> images{&targets.rt0(), &targets.rt1(), &targets.rt2(), &targets.rt3(),
                                           &targets.shadow_map()};
  for (std::size_t i = 0; i < images.size(); ++i) {
    write_image_descriptor(context, set0_, kImageBindings[i], sampler_.handle(), images[i]->view(),
                           VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  }
  if (targets.has_fragment_tags()) {
    write_image_descriptor(context, set0_, kFragmentTagsBinding, sampler_.handle(), targets.fragment_tags().view(),
                           VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  }
}

}  // namespace tilelight
