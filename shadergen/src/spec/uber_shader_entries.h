// uber_shader_entries.h - a spec with "uber_shaders" is compiled one entry at a time: each entry
// is the domain's permutations compiled from its uber-shader, with the companions that belong to
// it. The entries share the plan (features, table, pruned IDs), so the generated code has one
// typed API and one registry per entry.
#pragma once

#include <cstddef>

#include "shadergen/domain.h"

namespace shadergen {

// The number of uber-shaders `spec` compiles its permutations from: its "uber_shaders" entries,
// or 1 ("uber_shader" or "program").
std::size_t uber_shader_count(const DomainSpec& spec);

// The spec that entry `index` compiles: `uber` is the entry's file, `entry` its name and
// `companions` only those whose "uber_shader" names it (those naming none go with the first
// entry). Without "uber_shaders" (index 0) the spec itself. Precondition: index <
// uber_shader_count(spec).
DomainSpec for_uber_shader(const DomainSpec& spec, std::size_t index);

}  // namespace shadergen
