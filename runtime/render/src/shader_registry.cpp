#include "shader_registry.h"

#include "tilelight/vulkan/error.h"

#include <forward_1x_shaders.h>
#include <forward_shaders.h>
#include <local_lights_1x_shaders.h>
#include <local_lights_shaders.h>
#include <split_second_1x_shaders.h>
#include <split_second_branch_1x_shaders.h>
#include <split_second_branch_shaders.h>
#include <split_second_shaders.h>
#include <split_second_specialization_1x_shaders.h>
#include <split_second_specialization_shaders.h>

#include <string>

namespace tilelight {

// The two builds come from one spec; the generated constants must agree for the runtime to use
// either one's LUT with the other's blobs. The raster and compute light passes are two
// uber-shaders of that one spec ("uber_shaders"), so they share its table by construction.
static_assert(split_second::kRawCount == split_second_1x::kRawCount);
static_assert(split_second::kOptimisedCount == split_second_1x::kOptimisedCount);
static_assert(split_second::kRawToOptimised == split_second_1x::kRawToOptimised);
// And prune the same IDs: the renderer's draw classes and pruned set (tile_renderer.cpp) come
// from whichever registry draws, through its checked lookups, and must mean the same IDs.
static_assert(split_second::kRawPruned == split_second_1x::kRawPruned);

// The kinds builds differ from split_second only in how SKY and LIGHT_SCATTERING reach the
// shader: the same raw IDs, pruned by the same rule, and the same two uber-shaders. Their
// collapse is over the five variant features, so their optimised IDs are their own
// (light_classes.cpp pairs them with the values).
static_assert(split_second::kRawPruned == split_second_specialization::kRawPruned);
static_assert(split_second::kRawPruned == split_second_specialization_1x::kRawPruned);
static_assert(split_second::kRawPruned == split_second_branch::kRawPruned);
static_assert(split_second::kRawPruned == split_second_branch_1x::kRawPruned);
static_assert(split_second_specialization::kRawToOptimised == split_second_branch::kRawToOptimised);
static_assert(split_second_specialization::kRawToOptimised == split_second_specialization_1x::kRawToOptimised);
static_assert(split_second_branch::kRawToOptimised == split_second_branch_1x::kRawToOptimised);

namespace {

// One build's uber-shader `FORM` (raster or compute) as LightShaders: one table and one set of
// per-raw-ID values for both forms, each form its own registry of blobs.
// NOLINTBEGIN(bugprone-macro-parentheses): N and FORM are namespaces, which parentheses cannot hold.
#define TILELIGHT_LIGHT_SHADERS(N, FORM) \
  LightShaders { &N::FORM::registry(), &N::specialization, &N::branch_values, N::kBranchBlock }
// NOLINTEND(bugprone-macro-parentheses)

LightShaders raster_light_shaders(LightKinds kinds, bool single_sampled) {
  switch (kinds) {
    case LightKinds::variant:
      return single_sampled ? TILELIGHT_LIGHT_SHADERS(split_second_1x, raster)
                            : TILELIGHT_LIGHT_SHADERS(split_second, raster);
    case LightKinds::specialization:
      return single_sampled ? TILELIGHT_LIGHT_SHADERS(split_second_specialization_1x, raster)
                            : TILELIGHT_LIGHT_SHADERS(split_second_specialization, raster);
    case LightKinds::branch:
      return single_sampled ? TILELIGHT_LIGHT_SHADERS(split_second_branch_1x, raster)
                            : TILELIGHT_LIGHT_SHADERS(split_second_branch, raster);
  }
  throw Error("unknown light kinds");
}

LightShaders compute_light_shaders(LightKinds kinds, bool single_sampled) {
  switch (kinds) {
    case LightKinds::variant:
      return single_sampled ? TILELIGHT_LIGHT_SHADERS(split_second_1x, compute)
                            : TILELIGHT_LIGHT_SHADERS(split_second, compute);
    case LightKinds::specialization:
      return single_sampled ? TILELIGHT_LIGHT_SHADERS(split_second_specialization_1x, compute)
                            : TILELIGHT_LIGHT_SHADERS(split_second_specialization, compute);
    case LightKinds::branch:
      return single_sampled ? TILELIGHT_LIGHT_SHADERS(split_second_branch_1x, compute)
                            : TILELIGHT_LIGHT_SHADERS(split_second_branch, compute);
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
  return gbuffer_samples == VK_SAMPLE_COUNT_1_BIT ? split_second_1x::raster::registry()
                                                  : split_second::raster::registry();
}

const shadergen::Registry& compute_shaders_for(VkSampleCountFlagBits gbuffer_samples) {
  return gbuffer_samples == VK_SAMPLE_COUNT_1_BIT ? split_second_1x::compute::registry()
                                                  : split_second::compute::registry();
}

static_assert(local_lights::kRawPruned == local_lights_1x::kRawPruned);

const shadergen::Registry& local_light_shaders_for(VkSampleCountFlagBits gbuffer_samples) {
  return gbuffer_samples == VK_SAMPLE_COUNT_1_BIT ? local_lights_1x::registry() : local_lights::registry();
}

const shadergen::Registry& forward_shaders_for(VkSampleCountFlagBits gbuffer_samples) {
  return gbuffer_samples == VK_SAMPLE_COUNT_1_BIT ? forward_1x::registry() : forward::registry();
}

namespace {

// A namespace cannot be a template argument, so each domain's two builds (N and N_1x) fill their
// set through one macro that names every accessor once.
// NOLINTBEGIN(bugprone-macro-parentheses): N is a namespace, which parentheses cannot hold.
#define TILELIGHT_LIGHT_COMPANIONS(N)                                                                                  \
  LightCompanions {                                                                                                    \
    N::companions::lighting_dynamic(), N::companions::lighting_floor(), N::companions::tile(),                         \
        N::companions::tile_point(), N::companions::classify_tiles(), N::companions::tile_rects(),                     \
        N::companions::tile_prefix(), N::companions::scene(), N::companions::scene_masked(), N::companions::gbuffer(), \
        N::companions::gbuffer_flagged(), N::companions::gbuffer_masked(), N::companions::gbuffer_masked_flagged(),    \
        N::companions::sky_vertex(), N::companions::sky(), N::companions::sky_flagged(), N::companions::shadow(),      \
        N::companions::shadow_masked(), N::companions::shadow_mask(), N::companions::compute_lighting_dynamic(),       \
        N::companions::compute_lighting_floor(), N::companions::tile_lists()                                           \
  }
#define TILELIGHT_LOCAL_LIGHT_COMPANIONS(N)                                                                          \
  LocalLightCompanions {                                                                                             \
    N::companions::full_screen(), N::companions::volume(), N::companions::resolve(), N::companions::shadow_caster(), \
        N::companions::shadow_caster_masked(), N::companions::shadow_caster_mask()                                   \
  }
#define TILELIGHT_FORWARD_COMPANIONS(N) \
  ForwardCompanions { N::companions::vertex(), N::companions::full_screen(), N::companions::depth() }
// NOLINTEND(bugprone-macro-parentheses)

[[noreturn]] void unknown_registry(const shadergen::Registry& registry, const char* domain) {
  throw Error("the shader registry " + std::string(registry.name) + " is not a registry of the " + domain +
              " domain's builds");
}

}  // namespace

const LightCompanions& light_companions(VkSampleCountFlagBits gbuffer_samples) {
  static const LightCompanions multi = TILELIGHT_LIGHT_COMPANIONS(split_second);
  static const LightCompanions single = TILELIGHT_LIGHT_COMPANIONS(split_second_1x);
  return gbuffer_samples == VK_SAMPLE_COUNT_1_BIT ? single : multi;
}

const LocalLightCompanions& local_light_companions(VkSampleCountFlagBits gbuffer_samples) {
  static const LocalLightCompanions multi = TILELIGHT_LOCAL_LIGHT_COMPANIONS(local_lights);
  static const LocalLightCompanions single = TILELIGHT_LOCAL_LIGHT_COMPANIONS(local_lights_1x);
  return gbuffer_samples == VK_SAMPLE_COUNT_1_BIT ? single : multi;
}

const ForwardCompanions& forward_companions(VkSampleCountFlagBits gbuffer_samples) {
  static const ForwardCompanions multi = TILELIGHT_FORWARD_COMPANIONS(forward);
  static const ForwardCompanions single = TILELIGHT_FORWARD_COMPANIONS(forward_1x);
  return gbuffer_samples == VK_SAMPLE_COUNT_1_BIT ? single : multi;
}

#undef TILELIGHT_LIGHT_COMPANIONS
#undef TILELIGHT_LOCAL_LIGHT_COMPANIONS
#undef TILELIGHT_FORWARD_COMPANIONS

const LightCompanions& light_companions(const shadergen::Registry& registry) {
  if (&registry == &split_second::raster::registry() || &registry == &split_second::compute::registry())
    return light_companions(VK_SAMPLE_COUNT_4_BIT);
  if (&registry == &split_second_1x::raster::registry() || &registry == &split_second_1x::compute::registry())
    return light_companions(VK_SAMPLE_COUNT_1_BIT);
  unknown_registry(registry, "split_second");
}

const LocalLightCompanions& local_light_companions(const shadergen::Registry& registry) {
  if (&registry == &local_lights::registry()) return local_light_companions(VK_SAMPLE_COUNT_4_BIT);
  if (&registry == &local_lights_1x::registry()) return local_light_companions(VK_SAMPLE_COUNT_1_BIT);
  unknown_registry(registry, "local_lights");
}

const ForwardCompanions& forward_companions(const shadergen::Registry& registry) {
  if (&registry == &forward::registry()) return forward_companions(VK_SAMPLE_COUNT_4_BIT);
  if (&registry == &forward_1x::registry()) return forward_companions(VK_SAMPLE_COUNT_1_BIT);
  unknown_registry(registry, "forward");
}

}  // namespace tilelight
