#include "lighting_interface.h"

#include "descriptors.h"
#include "pipelines.h"
#include "reflected_layout.h"
#include "shader_registry.h"
#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <shadergen/vulkan.h>

#include <array>
#include <string>

namespace tilelight {
namespace {

// Binding numbers of lighting_params.glsl; the registry's reflection must agree (checked).
constexpr std::uint32_t kParamsBinding = 0;
constexpr std::array<std::uint32_t, 5> kImageBindings{1, 2, 3, 4, 5};
constexpr std::uint32_t kFragmentTagsBinding = 6;  // classification only, multisampled G-buffer
constexpr std::uint32_t kStorageSet = 1;           // the compute passes' output buffer

// The compute pass that binds set 0 and one output buffer in set 1 through compute_layout().
const shadergen::Reflection& classifier(const shadergen::Registry& registry) {
  return light_companions(registry).classify_tiles.shader.reflection;
}

// Set 0 of the light pass (the registry's merged layout) plus what the classifier alone reads
// from it (the coverage flags), from the classifier's own reflection.
std::vector<VkDescriptorSetLayoutBinding> set0_bindings(const shadergen::Registry& registry) {
  return merged_set_bindings({registry.pipeline_layout, classifier(registry).bindings}, 0, "lighting set 0");
}

// Set 1 of the compute passes: the one storage buffer the classifier writes (tile_classification.cpp
// binds it at binding 0).
std::vector<VkDescriptorSetLayoutBinding> storage_set_bindings(const shadergen::Registry& registry) {
  std::vector<VkDescriptorSetLayoutBinding> bindings =
      merged_set_bindings({classifier(registry).bindings}, kStorageSet, "compute output set");
  check_storage_buffers(bindings, 1, "compute output set");
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
  const std::size_t expected = 1 + kImageBindings.size() + (targets.has_coverage_flags() ? 1 : 0);
  if (bindings.size() != expected) {
    throw Error("the shader registry's set 0 has " + std::to_string(bindings.size()) +
                " bindings; the runtime expects the " + std::to_string(expected) + " of lighting_params.glsl");
  }
  for (VkDescriptorSetLayoutBinding& b : bindings) b.stageFlags |= VK_SHADER_STAGE_COMPUTE_BIT;
  set0_layout_ = create_descriptor_set_layout(context, bindings, "lighting set 0 layout");

  storage_set_layout_ =
      create_descriptor_set_layout(context, storage_set_bindings(registry), "compute output set layout");

  const std::array<VkDescriptorSetLayout, 1> lighting_sets{set0_layout_.get()};
  lighting_layout_ = create_pipeline_layout(context, lighting_sets, shadergen::vk::push_constant_ranges(registry),
                                            "lighting pipeline layout");
  const std::array<VkDescriptorSetLayout, 2> compute_sets{set0_layout_.get(), storage_set_layout_.get()};
  const std::vector<VkPushConstantRange> compute_push =
      merged_push_constant_ranges({&classifier(registry)}, VK_SHADER_STAGE_COMPUTE_BIT);
  compute_layout_ = create_pipeline_layout(context, compute_sets, compute_push, "classification pipeline layout");

  set0_ = allocate_descriptor_set(context, pool, set0_layout_.get(), "lighting set 0");
  write_buffer_descriptor(context, set0_, kParamsBinding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, params_.handle());
  const std::array<const Image*, 5> images{&targets.rt0(), &targets.rt1(), &targets.rt2(), &targets.rt3(),
                                           &targets.shadow_map()};
  for (std::size_t i = 0; i < images.size(); ++i) {
    write_image_descriptor(context, set0_, kImageBindings[i], sampler_.handle(), images[i]->view(),
                           VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  }
  if (targets.has_coverage_flags()) {
    write_image_descriptor(context, set0_, kFragmentTagsBinding, sampler_.handle(), targets.coverage_flags().view(),
                           VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  }
}

}  // namespace tilelight
