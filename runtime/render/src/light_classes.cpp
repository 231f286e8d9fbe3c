#include "light_classes.h"

#include "tilelight/vulkan/error.h"

#include <algorithm>
#include <string>
#include <utility>

namespace tilelight {
namespace {

// A pruned raw ID has no values (and no pipeline): empty ones, as a build without such features.
shadergen::Specialization specialization_of(const LightShaders& s, shadergen::RawId raw) {
  return s.specialization != nullptr ? s.specialization(raw).value_or(shadergen::Specialization{})
                                     : shadergen::Specialization{};
}

shadergen::BranchValues branch_of(const LightShaders& s, shadergen::RawId raw) {
  return s.branch_values != nullptr ? s.branch_values(raw).value_or(shadergen::BranchValues{})
                                    : shadergen::BranchValues{};
}

std::uint32_t add_pipeline(LightClasses& out, std::span<const std::uint32_t> spirv,
                           const shadergen::Specialization& specialization, std::string name) {
  out.pipelines.push_back({spirv, specialization, std::move(name)});
  return static_cast<std::uint32_t>(out.pipelines.size() - 1);
}

// One class and one pipeline per raw ID: the raw permutations, each with its own values (raw
// IDs whose blobs are the same are still drawn apart, as the variant build always drew them).
void raw_classes(LightClasses& out) {
  const shadergen::Registry& registry = *out.shaders.registry;
  for (std::uint32_t raw = 0; raw < out.class_for_raw.size(); ++raw) {
    const shadergen::RawId id(raw);
    LightClass c{raw, std::nullopt, branch_of(out.shaders, id)};
    if (const shadergen::Permutation* p = registry.find_raw(id)) {
      c.pipeline = add_pipeline(out, p->spirv, specialization_of(out.shaders, id), "raw " + std::to_string(raw));
    }
    out.class_for_raw[raw] = static_cast<std::uint8_t>(raw);
    out.classes.push_back(c);
  }
}

// What makes a class: the optimised ID and the values that travel beside it.
struct ClassKey {
  std::uint32_t optimised;
  shadergen::Specialization specialization;
  shadergen::BranchValues branch;
  std::uint32_t first_raw_id;
  bool operator==(const ClassKey& o) const {
    return optimised == o.optimised && specialization == o.specialization && branch == o.branch;
  }
};

void optimised_classes(LightClasses& out) {
  const shadergen::Registry& registry = *out.shaders.registry;
  const auto raw_count = static_cast<std::uint32_t>(out.class_for_raw.size());
  auto key_of = [&](std::uint32_t raw) -> std::optional<ClassKey> {
    const shadergen::RawId id(raw);
    const std::optional<shadergen::OptimisedId> optimised = registry.optimised_id(id);
    if (!optimised) return std::nullopt;  // pruned: no class, and the index builds refuse its tiles
    return ClassKey{optimised->value(), specialization_of(out.shaders, id), branch_of(out.shaders, id), raw};
  };
  // The distinct keys, each with the first raw ID that reaches it (raw IDs ascend)...
  std::vector<ClassKey> keys;
  for (std::uint32_t raw = 0; raw < raw_count; ++raw) {
    const std::optional<ClassKey> key = key_of(raw);
    if (key && std::find(keys.begin(), keys.end(), *key) == keys.end()) keys.push_back(*key);
  }
  // ... ordered by optimised ID, then by that raw ID: with no values beside the optimised IDs,
  // class c is optimised ID c, as the variant build has always drawn.
  std::stable_sort(keys.begin(), keys.end(),
                   [](const ClassKey& a, const ClassKey& b) { return a.optimised < b.optimised; });
  // One pipeline per (optimised ID, specialization values): classes that differ in their
  // branch values alone share one.
  std::vector<std::pair<std::uint32_t, shadergen::Specialization>> made;
  for (const ClassKey& key : keys) {
    const shadergen::Permutation* p = registry.find_optimised(shadergen::OptimisedId(key.optimised));
    if (p == nullptr) throw Error(std::string(registry.name) + ": no optimised permutation for a reachable ID");
    const std::pair<std::uint32_t, shadergen::Specialization> wanted{key.optimised, key.specialization};
    const auto found = std::find(made.begin(), made.end(), wanted);
    std::uint32_t pipeline = static_cast<std::uint32_t>(found - made.begin());
    if (found == made.end()) {
      std::string name = "optimised " + std::to_string(key.optimised);
      if (!key.specialization.map.empty()) name += " (as raw " + std::to_string(key.first_raw_id) + ")";
      pipeline = add_pipeline(out, p->spirv, key.specialization, std::move(name));
      made.push_back(wanted);
    }
    out.classes.push_back({key.first_raw_id, pipeline, key.branch});
  }
  if (out.classes.size() > 256) throw Error("more than 256 draw classes: a class no longer fits a byte");
  for (std::uint32_t raw = 0; raw < raw_count; ++raw) {
    const std::optional<ClassKey> key = key_of(raw);
    if (!key) continue;
    const auto at = std::find_if(out.classes.begin(), out.classes.end(),
                                 [&](const LightClass& c) { return key == key_of(c.first_raw_id); });
    out.class_for_raw[raw] = static_cast<std::uint8_t>(at - out.classes.begin());
  }
}

}  // namespace

LightClasses light_classes(const LightShaders& shaders, PermutationSet permutations) {
  LightClasses out;
  out.shaders = shaders;
  out.class_for_raw.assign(shaders.registry->raw.size(), 0);
  if (permutations == PermutationSet::raw) {
    raw_classes(out);
  } else {
    optimised_classes(out);
  }
  return out;
}

}  // namespace tilelight
