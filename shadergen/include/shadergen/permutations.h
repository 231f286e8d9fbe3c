// shadergen/permutations.h - expanding a domain into raw and optimised permutations and the
// lookup table between them. Pure functions of the spec: no files, no compiler.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "shadergen/diagnostic.h"
#include "shadergen/domain.h"

namespace shadergen {

struct RawPermutation {
  std::uint32_t id = 0;
  std::vector<std::string> defines;  // GLSL defines, in raw bit order ("NAME" or "NAME=VALUE")
  bool pruned = false;               // matches an impossible rule or holds no value: never compiled
  int pruned_by = -1;                // index into DomainSpec::impossible, or -1
  int unvalued = -1;                 // index into DomainSpec::raw_features of a valued feature
                                     // whose field holds no value, or -1
  std::uint32_t optimised = 0;       // the lookup table's entry
};

struct OptimisedPermutation {
  std::uint32_t id = 0;
  std::vector<std::string> defines;
  std::uint32_t raw_equivalent = 0;  // the raw ID with the same defines (same source)
  std::uint32_t raw_mapped = 0;      // how many non-pruned raw IDs map here
};

struct PermutationPlan {
  std::vector<RawPermutation> raw;              // indexed by raw ID
  std::vector<OptimisedPermutation> optimised;  // indexed by optimised ID
};

// Expands the domain. Fails when an optimised ID would be compiled with an impossible raw
// feature set, or when a non-pruned raw ID maps to an optimised ID... (cannot happen: every
// value < 2^M exists; the generated code still static_asserts it).
Result<PermutationPlan> expand(const DomainSpec& spec);

// The optimised ID the rules give for a raw ID (ignores pruning).
std::uint32_t apply_rules(const DomainSpec& spec, std::uint32_t raw_id);

// "SHADOW_SOFT | SUN_LIGHT", or "(none)" for 0.
std::string describe_bits(const std::vector<std::string>& names, std::uint32_t bits);
// A raw ID by its features: "FOG | TAA_QUALITY=2" (a valued feature always shows its value,
// or "NAME=?" when its field holds none), "(none)" when nothing is set.
std::string describe_raw(const DomainSpec& spec, std::uint32_t raw_id);

// Human-readable views for the CLI.
std::string format_lut(const DomainSpec& spec, const PermutationPlan& plan);
std::string format_list(const DomainSpec& spec, const PermutationPlan& plan);
// Precondition: raw_id < spec.raw_count().
std::string format_explanation(const DomainSpec& spec, const PermutationPlan& plan, std::uint32_t raw_id);

}  // namespace shadergen
