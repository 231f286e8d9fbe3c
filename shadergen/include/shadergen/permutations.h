// shadergen/permutations.h - expanding a domain into raw and optimised permutations and the
// lookup table between them. Pure functions of the spec: no files, no compiler.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "shadergen/diagnostic.h"
#include "shadergen/domain.h"

namespace shadergen {

// A raw ID's record: a few words, so that 2^20 of them fit in memory (its defines are computed
// when needed: raw_defines()).
struct RawPermutation {
  std::uint32_t id = 0;
  bool pruned = false;          // matches an impossible rule or holds no value: never compiled
  int pruned_by = -1;           // index into DomainSpec::impossible, or -1
  int unvalued = -1;            // index into DomainSpec::raw_features of a valued feature
                                // whose field holds no value, or -1
  std::uint32_t optimised = 0;  // the lookup table's entry
};

struct OptimisedPermutation {
  std::uint32_t id = 0;
  std::vector<std::string> defines;
  std::uint32_t raw_equivalent = 0;  // the raw ID with the same defines (same source)
  std::uint32_t raw_mapped = 0;      // how many non-pruned raw IDs map here
};

// What a domain builds. Both lists ascend by ID. An enumerated domain (no variants file) holds
// every raw ID, pruned or not, and every optimised ID, so that raw[i].id == i and
// optimised[i].id == i. With a variants file they hold only the listed raw IDs and the
// optimised IDs those map to: the plan grows with what is built, not with the raw space.
struct PermutationPlan {
  std::vector<RawPermutation> raw;
  std::vector<OptimisedPermutation> optimised;

  // Where raw ID `id` is in `raw`, or nullopt when the plan does not hold it (outside the
  // domain, or not listed). Constant time when enumerated, else a binary search.
  std::optional<std::size_t> raw_position(std::uint32_t id) const;
  std::optional<std::size_t> optimised_position(std::uint32_t id) const;
  const RawPermutation* find_raw(std::uint32_t id) const;  // nullptr when not held
  const OptimisedPermutation* find_optimised(std::uint32_t id) const;
};

// Expands the domain: every raw ID up to kMaxEnumeratedRawBits raw bits, else the ones
// spec.listed_raw_ids holds (read_variants_file() fills them; an enumerated domain may list
// too). Fails when a wider domain lists nothing (naming the 2^20 limit and "variants_file"),
// or when an optimised ID that is built would be compiled with an impossible raw feature set or
// with two values of one feature. Time and memory grow with the IDs built, never with 2^32.
Result<PermutationPlan> expand(const DomainSpec& spec);

// The GLSL defines raw ID `raw_id` is compiled with, in raw bit order ("NAME" or "NAME=VALUE";
// none for a valued feature whose field holds no value).
std::vector<std::string> raw_defines(const DomainSpec& spec, std::uint32_t raw_id);

// The index into spec.impossible of the first rule that prunes `raw_id`, or -1 when none does.
// Every check of a raw ID against the impossible rules goes through here (expand(), a variants
// file's lines), so they agree on which rule is named.
int first_impossible_rule(const DomainSpec& spec, std::uint32_t raw_id);

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
// Any raw ID of the domain (precondition: raw_id < spec.raw_space()), built or not.
std::string format_explanation(const DomainSpec& spec, const PermutationPlan& plan, std::uint32_t raw_id);

}  // namespace shadergen
