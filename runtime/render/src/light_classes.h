#pragma once
// The tile pass's draw classes for one build of the light domain (LightShaders). With every
// feature a variant, a class is an optimised ID (or, drawing raw permutations, a raw ID) and its
// pipeline that permutation's. When some features are specialization constants or run-time
// branches, raw IDs that differ only in those share a blob but not a frame: a class is then an
// (optimised ID, specialization values, branch values) triple that some possible raw ID reaches.
// Classes with equal optimised ID and specialization values share a pipeline (all of one
// optimised ID's, for a build whose non-variant features are all branches); each class's draws
// carry its own branch values (branch_set.h).

#include "lighting_passes.h"
#include "shader_registry.h"

#include <shadergen/registry.h>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace tilelight {

// One pipeline the tile pass creates: a blob and the specialization data it is created with.
struct LightPipelineSpec {
  std::span<const std::uint32_t> spirv;
  shadergen::Specialization specialization;
  std::string name;  // "optimised 5", "optimised 5 (LIGHT_SCATTERING | SKY)", "raw 17"
};

struct LightClass {
  std::uint32_t first_raw_id = 0;         // the smallest raw ID drawn in this class
  std::optional<std::uint32_t> pipeline;  // into LightClasses::pipelines; none: a pruned raw ID's class
  shadergen::BranchValues branch;         // the class's branch block (size 0: no branch features)
};

struct LightClasses {
  LightShaders shaders;
  std::vector<LightClass> classes;           // in order of optimised ID, then of first raw ID
  std::vector<LightPipelineSpec> pipelines;  // in order of first use by the classes
  std::vector<std::uint8_t> class_for_raw;   // every raw ID's class (0 for a pruned one)
  std::uint32_t class_count() const { return static_cast<std::uint32_t>(classes.size()); }
};

// The draw classes of `shaders` (optimised: every optimised ID with each set of values some raw
// ID takes; raw: one class per raw ID, pruned ones without a pipeline). For a variant-only
// build that is the optimised (or raw) IDs themselves, in their order: class c is ID c.
LightClasses light_classes(const LightShaders& shaders, PermutationSet permutations);

}  // namespace tilelight
