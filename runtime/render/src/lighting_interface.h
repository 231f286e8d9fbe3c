#pragma once
// The descriptor interface shared by classification and every lighting permutation
// (uber/include/lighting_params.glsl): set 0 is built from the registry's merged layout, so the
// generated code, not this file, says which bindings exist. Set 1 is one storage buffer for a
// compute pass that writes a result (classification; the tests' G-buffer dump binds a layout of
// its own with the same set 0), and the push constants are what the classifier's reflection
// declares: a shader change cannot disagree silently.

#include "render_targets.h"
#include "shader_registry.h"
#include "tilelight/scene/uniform_blocks.h"
#include "tilelight/vulkan/buffer.h"
#include "tilelight/vulkan/sampler.h"
#include "tilelight/vulkan/vk_handles.h"

namespace tilelight {

class Context;

class LightingInterface {
 public:
  LightingInterface(const Context& context, const LightingParamsBlock& params, const RenderTargets& targets,
                    VkDescriptorPool pool);

  VkDescriptorSetLayout set0_layout() const { return set0_layout_.get(); }
  VkDescriptorSetLayout storage_set_layout() const { return storage_set_layout_.get(); }
  VkDescriptorSet set0() const { return set0_; }
  // Lighting pipelines: set 0 + the registry's push-constant range (the tile vertex shader's).
  VkPipelineLayout lighting_layout() const { return lighting_layout_.get(); }
  // Classification: set 0, set 1 (one storage buffer), classify_tiles's push constants (its
  // grid).
  VkPipelineLayout compute_layout() const { return compute_layout_.get(); }
  const LightingParamsBlock& params() const { return params_block_; }
  // The shaders that read this G-buffer (shaders_for() its sample count): every pass that binds
  // set 0 takes its pipelines from here.
  const shadergen::Registry& shaders() const { return *shaders_; }

 private:
  const shadergen::Registry* shaders_;
  LightingParamsBlock params_block_;
  Buffer params_;
  Sampler sampler_;
  UniqueDescriptorSetLayout set0_layout_, storage_set_layout_;
  UniquePipelineLayout lighting_layout_, compute_layout_;
  VkDescriptorSet set0_ = VK_NULL_HANDLE;
};

}  // namespace tilelight
