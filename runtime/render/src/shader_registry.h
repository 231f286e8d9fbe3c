#pragma once
// Every shader the runtime runs comes from a registry that shadergen generated at build time
// from permutations/split_second.json: the 32 optimised and 128 raw lighting permutations and
// the non-permuted companions (classification, index build, scene, tile vertex shaders).
//
// The domain is built twice: as it is, for a multisampled G-buffer (split_second), and with
// GBUFFER_SINGLE_SAMPLED defined (split_second_1x), whose shaders read the G-buffer as
// sampler2D, since a single-sampled image may not be bound to a sampler2DMS. Both builds share
// the spec, so their lookup tables and raw/optimised IDs are the same; only the blobs differ.

#include "tilelight/render/tile_renderer.h"

#include <shadergen/registry.h>

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <string_view>

namespace tilelight {

// The registry whose shaders read a G-buffer of `gbuffer_samples` samples per pixel.
const shadergen::Registry& shaders_for(VkSampleCountFlagBits gbuffer_samples);

// The compute form of the light pass (permutations/split_second_compute.json: the same domain,
// uber/lighting.comp), for a G-buffer of `gbuffer_samples` samples per pixel. Its LUT and IDs are
// those of shaders_for() (static_asserted).
const shadergen::Registry& compute_shaders_for(VkSampleCountFlagBits gbuffer_samples);

// One build of the light domain as the tile pass draws it (RendererOptions::light_kinds): its
// registry (raster or compute form, for the G-buffer's sample count) and the generated values
// its non-variant features take per raw ID. A variant build's functions return empty data.
struct LightShaders {
  const shadergen::Registry* registry = nullptr;
  // N::specialization() and N::branch_values() of the build's namespace.
  shadergen::Specialization (*specialization)(shadergen::RawId) = nullptr;
  shadergen::BranchValues (*branch_values)(shadergen::RawId) = nullptr;
  shadergen::BranchBlock branch_block{};  // N::kBranchBlock: size 0 without branch features
};

// The build of `kinds` in the form of `pass` whose shaders read a G-buffer of `gbuffer_samples`
// samples per pixel. Its raw IDs and pruned set are those of shaders_for() (static_asserted).
LightShaders light_shaders_for(LightKinds kinds, LightPass pass, VkSampleCountFlagBits gbuffer_samples);

// The local-light passes (permutations/local_lights.json: uber/local_light.frag and its vertex
// shaders), for a G-buffer of `gbuffer_samples` samples per pixel. Same raw IDs in both builds.
const shadergen::Registry& local_light_shaders_for(VkSampleCountFlagBits gbuffer_samples);

// The forward pass for blended materials (permutations/forward.json: uber/forward.frag, its
// vertex shader and depth copy), for a G-buffer of `gbuffer_samples` samples per pixel.
const shadergen::Registry& forward_shaders_for(VkSampleCountFlagBits gbuffer_samples);

// The companion shader `name` of `registry` (its SPIR-V and reflection); throws tilelight::Error
// naming both when there is none.
const shadergen::Permutation& companion_shader(const shadergen::Registry& registry, std::string_view name);
// Its SPIR-V.
std::span<const std::uint32_t> companion_spirv(const shadergen::Registry& registry, std::string_view name);

}  // namespace tilelight
