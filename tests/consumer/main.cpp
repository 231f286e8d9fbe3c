// Checks that the generated registry links and holds what the manifest promises, and that the
// generated API's contract compiles outside the project: Features with designated
// initializers, raw_id(), kFeatures, kDefines, find_raw_id() and to_string() in the one
// grammar, is_possible(), the typed IDs and bits, the checked lookups by raw ID and (with
// CONSUMER_VULKAN, CMakeLists.txt) shadergen/vulkan.h.
#include <consumer_shaders.h>
#if CONSUMER_VULKAN
#include <shadergen/vulkan.h>
#endif

#include <cstdio>
#include <string>

namespace shaders = game::shaders;

// The toy domain lists SOFT (bit 2) before LIT (bit 0): designated initializers follow the spec.
using shaders::RawId;
static_assert(shaders::raw_id({.SOFT = true, .DISTORT = true}) == RawId(0b1100u));
static_assert(shaders::find_raw_id("SOFT|DISTORT") == RawId(0b1100u));
static_assert(shaders::find_raw_id("SOFT|DISTORT") == (RawId(0) | shaders::raw_bit::SOFT | shaders::raw_bit::DISTORT));
static_assert(shaders::find_raw_id("") == RawId(0));
static_assert(shaders::find_raw_id("(none)") == RawId(0));
static_assert(!shaders::find_raw_id("LIT|DISTORT") && !shaders::is_possible({.LIT = true, .DISTORT = true}), "pruned");
static_assert(!shaders::find_raw_id("SOFT|NOT_A_FEATURE"));
static_assert(!shaders::find_raw_id("SOFT_PARTICLES") && !shaders::find_raw_id("12") &&
              !shaders::find_raw_id("SOFT=1"));
static_assert(!shaders::raw_id({.LIT = true, .DISTORT = true}), "pruned");
static_assert(shaders::optimised_id(RawId(shaders::kRawCount)) == std::nullopt &&
              !shaders::is_valid_raw_id(RawId(0xffffffffu)));
static_assert(shaders::features(RawId(0b1100u)).SOFT && !shaders::features(RawId(0b1100u)).LIT);
static_assert(shaders::kFeatures[0].name == "SOFT" && shaders::kFeatures[0].bit == 2);

int main() {
  const shadergen::Registry& registry = shaders::registry();
  if (registry.raw.size() != shaders::kRawCount) return 1;
  if (registry.optimised.size() != shaders::kOptimisedCount) return 2;
  for (const shadergen::Permutation& p : registry.raw) {
    if (p.pruned != shaders::kRawPruned[p.id]) return 3;
    if (!p.pruned && (p.spirv.empty() || p.spirv[0] != 0x07230203u)) return 4;
    if (registry.raw_to_optimised[p.id] != shaders::kRawToOptimised[p.id]) return 5;
    // Every raw ID by its feature names, through find_raw_id(): none when pruned.
    const RawId id(p.id);
    std::string names;
    for (const shadergen::Feature& f : shaders::kFeatures)
      if (p.id & (1u << f.bit)) names += (names.empty() ? "" : "|") + std::string(f.name);
    if (shaders::find_raw_id(names) != (p.pruned ? std::nullopt : std::optional<RawId>(id))) return 6;
    if (!p.pruned && shaders::find_raw_id(shaders::to_string(id)) != id) return 12;
#if CONSUMER_VULKAN
    if (!p.pruned && shadergen::vk::shader_module_create_info(p).codeSize != p.spirv.size() * 4) return 7;
#endif
    // The checked lookups: none for a pruned ID, the table's permutation otherwise.
    const shadergen::Permutation* drawn = registry.optimised_for_raw(id);
    if (p.pruned ? drawn != nullptr : drawn != &registry.optimised[shaders::kRawToOptimised[p.id]]) return 10;
  }
  // An ID past the table is none everywhere, never a read past it.
  for (std::uint32_t outside : {shaders::kRawCount, shaders::kRawCount + 16, 0xffffffffu})
    if (registry.find_raw(RawId(outside)) || registry.optimised_for_raw(RawId(outside)) ||
        shaders::optimised_id(RawId(outside)))
      return 11;
  if (!shaders::kDefines.empty()) return 8;
#if CONSUMER_VULKAN
  std::size_t bindings = 0;
  for (std::uint32_t set = 0; set < shadergen::vk::descriptor_set_count(registry.pipeline_layout); ++set)
    bindings += shadergen::vk::descriptor_set_layout_bindings(registry.pipeline_layout, set).size();
  if (bindings != registry.pipeline_layout.size()) return 9;
#endif
  std::printf("consumer: %s: %zu raw, %zu optimised permutations (%s shadergen/vulkan.h)\n", registry.name.data(),
              registry.raw.size(), registry.optimised.size(), CONSUMER_VULKAN ? "with" : "without");
  return 0;
}
