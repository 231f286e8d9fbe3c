#include "shader_registry.h"

#include "tilelight/vulkan/error.h"

#include <forward_1x_shaders.h>
#include <forward_shaders.h>
#include <local_lights_1x_shaders.h>
#include <local_lights_shaders.h>
#include <split_second_1x_shaders.h>
#include <split_second_branch_1x_shaders.h>
#include <split_second_branch_compute_1x_shaders.h>
#include <split_second_branch_compute_shaders.h>
#include <split_second_branch_shaders.h>
#include <split_second_compute_1x_shaders.h>
#include <split_second_compute_shaders.h>
#include <split_second_shaders.h>
#include <split_second_specialization_1x_shaders.h>
#include <split_second_specialization_compute_1x_shaders.h>
#include <split_second_specialization_compute_shaders.h>
#include <split_second_specialization_shaders.h>

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

// The kinds builds differ from split_second only in how SKY and LIGHT_SCATTERING reach the
// shader: the same raw IDs, pruned by the same rule. Their collapse is over the five variant
// features, so their optimised IDs are their own (light_classes.cpp pairs them with the values).
static_assert(split_second::kRawPruned == split_second_specialization::kRawPruned);
static_assert(split_second::kRawPruned == split_second_specialization_1x::kRawPruned);
static_assert(split_second::kRawPruned == split_second_specialization_compute::kRawPruned);
static_assert(split_second::kRawPruned == split_second_specialization_compute_1x::kRawPruned);
static_assert(split_second::kRawPruned == split_second_branch::kRawPruned);
static_assert(split_second::kRawPruned == split_second_branch_1x::kRawPruned);
static_assert(split_second::kRawPruned == split_second_branch_compute::kRawPruned);
static_assert(split_second::kRawPruned == split_second_branch_compute_1x::kRawPruned);
static_assert(split_second_specialization::kRawToOptimised == split_second_branch::kRawToOptimised);
static_assert(split_second_specialization::kRawToOptimised == split_second_specialization_compute::kRawToOptimised);
static_assert(split_second_branch::kRawToOptimised == split_second_branch_compute::kRawToOptimised);

namespace {

// One namespace's build as LightShaders.
#define TILELIGHT_LIGHT_SHADERS(N) \
  LightShaders { &N::registry(), &N::specialization, &N::branch_values, N::kBranchBlock }

LightShaders raster_light_shaders(LightKinds kinds, bool single_sampled) {
  switch (kinds) {
    case LightKinds::variant:
      return single_sampled ? TILELIGHT_LIGHT_SHADERS(split_second_1x) : TILELIGHT_LIGHT_SHADERS(split_second);
    case LightKinds::specialization:
      return single_sampled ? TILELIGHT_LIGHT_SHADERS(split_second_specialization_1x)
                            : TILELIGHT_LIGHT_SHADERS(split_second_specialization);
    case LightKinds::branch:
      return single_sampled ? TILELIGHT_LIGHT_SHADERS(split_second_branch_1x)
                            : TILELIGHT_LIGHT_SHADERS(split_second_branch);
  }
  throw Error("unknown light kinds");
}

LightShaders compute_light_shaders(LightKinds kinds, bool single_sampled) {
  switch (kinds) {
    case LightKinds::variant:
      return single_sampled ? TILELIGHT_LIGHT_SHADERS(split_second_compute_1x)
                            : TILELIGHT_LIGHT_SHADERS(split_second_compute);
    case LightKinds::specialization:
      return single_sampled ? TILELIGHT_LIGHT_SHADERS(split_second_specialization_compute_1x)
                            : TILELIGHT_LIGHT_SHADERS(split_second_specialization_compute);
    case LightKinds::branch:
      return single_sampled ? TILELIGHT_LIGHT_SHADERS(split_second_branch_compute_1x)
                            : TILELIGHT_LIGHT_SHADERS(split_second_branch_compute);
  }
  throw Error("unknown light kinds");
}

#undef TILELIGHT_LIGHT_SHADERS

}  // namespace

LightShaders light_shaders_for(LightKinds kinds, LightPass pass, VkSampleCountFlagBits gbuffer_samples) {
  const bool single_sampled = gbuffer_samples == VK_SAMPLE_COUNT_1_BIT;
  return pass == LightPass::compute ? compute_light_shaders(kinds, single_sampled)
                                    : raster_light_shaders(kinds, single_sampled);
}

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
