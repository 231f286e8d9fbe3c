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
#include <optional>

namespace tilelight {

// The registry whose shaders read a G-buffer of `gbuffer_samples` samples per pixel.
const shadergen::Registry& shaders_for(VkSampleCountFlagBits gbuffer_samples);

// The compute form of the light pass (the "compute" uber-shader of permutations/split_second.json:
// the same domain, uber/lighting.comp), for a G-buffer of `gbuffer_samples` samples per pixel.
// Its LUT and IDs are those of shaders_for(): one spec, one table.
const shadergen::Registry& compute_shaders_for(VkSampleCountFlagBits gbuffer_samples);

// One build of the light domain as the tile pass draws it (RendererOptions::light_kinds): its
// registry (raster or compute form, for the G-buffer's sample count) and the generated values
// its non-variant features take per raw ID. A variant build's functions return empty data.
struct LightShaders {
  const shadergen::Registry* registry = nullptr;
  // N::specialization() and N::branch_values() of the build's namespace: nullopt for a raw ID
  // that is out of range or pruned.
  std::optional<shadergen::Specialization> (*specialization)(shadergen::RawId) = nullptr;
  std::optional<shadergen::BranchValues> (*branch_values)(shadergen::RawId) = nullptr;
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

// The companion shaders of each domain by the names its spec gives them, taken from the
// generated typed accessors (N::companions::<name>()): a companion renamed or removed in a spec
// breaks the build here rather than a run. One set per build of the domain (multisampled or
// single-sampled G-buffer); each member is also in its registry's `companions`.
struct LightCompanions {  // permutations/split_second.json
  // With the raster light pass (uber-shader "raster"): its baselines and tile vertex shaders,
  // the classification and index build, and the scene passes.
  const shadergen::CompanionShader &lighting_dynamic, &lighting_floor, &tile, &tile_point;
  const shadergen::CompanionShader &classify_tiles, &tile_rects, &tile_prefix;
  const shadergen::CompanionShader &scene, &scene_masked, &gbuffer, &gbuffer_flagged, &gbuffer_masked,
      &gbuffer_masked_flagged;
  const shadergen::CompanionShader &sky_vertex, &sky, &sky_flagged, &shadow, &shadow_masked, &shadow_mask;
  // With the compute light pass (uber-shader "compute"): its baselines and the tile-list build.
  const shadergen::CompanionShader &compute_lighting_dynamic, &compute_lighting_floor, &tile_lists;
};

struct LocalLightCompanions {  // permutations/local_lights.json
  const shadergen::CompanionShader &full_screen, &volume, &resolve;
  const shadergen::CompanionShader &shadow_caster, &shadow_caster_masked, &shadow_caster_mask;
};

struct ForwardCompanions {  // permutations/forward.json
  const shadergen::CompanionShader &vertex, &full_screen, &depth;
};

// The set of the build that reads a G-buffer of `gbuffer_samples` samples per pixel.
const LightCompanions& light_companions(VkSampleCountFlagBits gbuffer_samples);
const LocalLightCompanions& local_light_companions(VkSampleCountFlagBits gbuffer_samples);
const ForwardCompanions& forward_companions(VkSampleCountFlagBits gbuffer_samples);

// The set of the build `registry` is a registry of (a pass holds the registry it was made
// with); throws tilelight::Error naming the registry when it is none of that domain's.
const LightCompanions& light_companions(const shadergen::Registry& registry);
const LocalLightCompanions& local_light_companions(const shadergen::Registry& registry);
const ForwardCompanions& forward_companions(const shadergen::Registry& registry);

}  // namespace tilelight
