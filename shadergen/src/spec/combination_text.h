// combination_text.h - the words for raw IDs written as text. The grammar and its one parser,
// shadergen::parse_combination(), are in shadergen/registry.h (header-only, so the generated
// find_raw_id() uses them too); this says in words why a text was refused, for `shadergen
// explain` and for any spec file that names raw feature combinations.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "shadergen/domain.h"
#include "shadergen/registry.h"

namespace shadergen {

// A spec's raw features as shadergen::Feature, in spec order (the order of the generated
// kFeatures, so a message lists them as the generated code does). It views the spec's
// strings: the spec must outlive it.
class FeatureTable {
 public:
  explicit FeatureTable(const DomainSpec& spec);
  // The features' `values` point into values_: a copy would point into the original's.
  FeatureTable(const FeatureTable&) = delete;
  FeatureTable& operator=(const FeatureTable&) = delete;
  FeatureTable(FeatureTable&&) = default;
  FeatureTable& operator=(FeatureTable&&) = default;

  std::span<const Feature> features() const { return features_; }

 private:
  std::vector<std::vector<std::string_view>> values_;
  std::vector<Feature> features_;
};

// Why parse_combination() refused a text, naming the offending word, e.g.
//   "SOFT_SHADOW" is the define of feature SHADOW_SOFT; name the feature
//   TAA_QUALITY has no value "7" (values: 0, 1, 2)
// `features` are the ones the text was parsed against. Empty when `parsed` holds no error.
std::string describe_combination_error(const ParsedCombination& parsed, std::span<const Feature> features);

}  // namespace shadergen
