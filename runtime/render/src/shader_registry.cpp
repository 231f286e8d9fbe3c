#include "shader_registry.h"

#include "tilelight/vulkan/error.h"

#include <forward_1x_shaders.h>
#include <forward_shaders.h>
#include <local_lights_1x_shaders.h>
#include <local_lights_shaders.h>
#include <split_second_1x_shaders.h>
#include <split_second_compute_1x_shaders.h>
#include <split_second_compute_shaders.h>
#include <split_second_shaders.h>

#include <string>

namespace tilelight {

// The two builds come from one spec; the generated constants must agree for the runtime to use
// either one's LUT with the other's blobs.
static_assert(split_second::kRawCount == split_second_1x::kRawCount);
static_assert(split_second::kOptimisedCount == split_second_1x::kOptimisedCount);
static_assert(split_second::kRawToOptimised == split_second_1x::kRawToOptimised);
// The compute form's spec repeats the domain: it must collapse exactly as the fragment form does.
static_assert(split_second::kRawCount == split_second_compute::kRawCount);
static_assert(split_second::kOptimisedCount == split_second_compute::kOptimisedCount);
static_assert(split_second::kRawToOptimised == split_second_compute::kRawToOptimised);
static_assert(split_second::kRawToOptimised == split_second_compute_1x::kRawToOptimised);
// And prune the same IDs: the renderer's draw classes and pruned set (tile_renderer.cpp) come
// from whichever registry draws, through its checked lookups, and must mean the same IDs.
static_assert(split_second::kRawPruned == split_second_1x::kRawPruned);
static_assert(split_second::kRawPruned == split_second_compute::kRawPruned);
static_assert(split_second::kRawPruned == split_second_compute_1x::kRawPruned);

const shadergen::Registry& shaders_for(VkSampleCountFlagBits gbuffer_samples) {
  return gbuffer_samples == VK_SAMPLE_COUNT_1_BIT ? split_second_1x::registry() : split_second::registry();
}

const shadergen::Registry& compute_shaders_for(VkSampleCountFlagBits gbuffer_samples) {
  return gbuffer_samples == VK_SAMPLE_COUNT_1_BIT ? split_second_compute_1x::registry()
                                                  : split_second_compute::registry();
}

static_assert(local_lights::kRawPruned == local_lights_1x::kRawPruned);

const shadergen::Registry& local_light_shaders_for(VkSampleCountFlagBits gbuffer_samples) {
  return gbuffer_samples == VK_SAMPLE_COUNT_1_BIT ? local_lights_1x::registry() : local_lights::registry();
}

const shadergen::Registry& forward_shaders_for(VkSampleCountFlagBits gbuffer_samples) {
  return gbuffer_samples == VK_SAMPLE_COUNT_1_BIT ? forward_1x::registry() : forward::registry();
}

const shadergen::Permutation& companion_shader(const shadergen::Registry& registry, std::string_view name) {
  const shadergen::CompanionShader* shader = registry.companion(name);
  if (shader == nullptr) {
    throw Error("the shader registry " + std::string(registry.name) + " has no companion shader '" + std::string(name) +
                "'");
  }
  return shader->shader;
}

std::span<const std::uint32_t> companion_spirv(const shadergen::Registry& registry, std::string_view name) {
  return companion_shader(registry, name).spirv;
}

}  // namespace tilelight
