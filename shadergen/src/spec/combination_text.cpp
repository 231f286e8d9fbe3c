#include "spec/combination_text.h"

#include <algorithm>

#include "base/closest_name.h"
#include "base/untrusted_text.h"
#include "spec/defines.h"

namespace shadergen {
namespace {

// The word as written, quoted; a word from a command line or a file may hold anything.
std::string quoted(std::string_view word) { return std::string("\"").append(printable(word, 200)).append("\""); }

std::string joined(std::span<const std::string_view> names) {
  std::string text;
  for (std::string_view name : names) text += (text.empty() ? "" : ", ") + std::string(name);
  return text;
}

std::string feature_names(std::span<const Feature> features) {
  std::vector<std::string_view> names;
  for (const Feature& f : features) names.push_back(f.name);
  return joined(names);
}

std::string empty_word(const ParsedCombination& parsed) {
  if (parsed.word.empty())
    return "an empty word at offset " + std::to_string(parsed.position) +
           ": two '|' in a row, or one at the start or the end";
  return quoted(parsed.word) + " names no feature before its '='";
}

std::string unknown_name(const ParsedCombination& parsed, std::span<const Feature> features) {
  if (parsed.word == "(none)") return "\"(none)\" stands alone: it means every feature off";
  // Only a word that could be a name is a misspelt one: "SKY+SUN_LIGHT" is a wrong separator (and
  // would "extend" SKY), and a word past 64 characters would cost its length times every name's.
  std::vector<std::string> known;
  for (const Feature& f : features) known.emplace_back(f.name);
  const std::optional<std::string> meant = is_identifier(parsed.word) ? closest_name(parsed.word, known) : std::nullopt;
  return "unknown feature " + quoted(parsed.word) + " (known: " + feature_names(features) + ")" +
         (meant ? "; did you mean " + *meant + "?" : std::string());
}

std::string about_feature(const ParsedCombination& parsed, const Feature& f) {
  const std::string name(f.name);
  switch (parsed.error) {
    case CombinationError::define_name:
      return quoted(parsed.word) + " is the define of feature " + name + "; name the feature";
    case CombinationError::boolean_with_value:
      return "feature " + name + " is a boolean: write " + name + " alone, or leave it out (" +
             printable(parsed.word, 200) + " is not accepted)";
    case CombinationError::missing_value:
      return "feature " + name + " takes a value: write " + name + "=<value> (values: " + joined(f.values) + ")";
    case CombinationError::unknown_value:
      return name + " has no value " + quoted(parsed.word) + " (values: " + joined(f.values) + ")";
    case CombinationError::repeated:
      return "feature " + name + " is named twice (again as " + quoted(parsed.word) + "); name each feature once";
    default: return {};
  }
}

}  // namespace

FeatureTable::FeatureTable(const DomainSpec& spec) {
  std::vector<const RawFeature*> ordered;
  for (const RawFeature& f : spec.raw_features) ordered.push_back(&f);
  std::sort(ordered.begin(), ordered.end(),
            [](const RawFeature* a, const RawFeature* b) { return a->spec_order < b->spec_order; });
  // Every inner vector is filled before any span points into it: the outer one never regrows.
  values_.reserve(ordered.size());
  for (const RawFeature* f : ordered) values_.emplace_back(f->values.begin(), f->values.end());
  for (std::size_t i = 0; i < ordered.size(); ++i)
    features_.push_back({ordered[i]->name, ordered[i]->define, ordered[i]->bit, ordered[i]->width, values_[i]});
}

std::string describe_combination_error(const ParsedCombination& parsed, std::span<const Feature> features) {
  switch (parsed.error) {
    case CombinationError::none: return {};
    case CombinationError::empty_word: return empty_word(parsed);
    case CombinationError::unknown_name: return unknown_name(parsed, features);
    case CombinationError::number:
      return quoted(parsed.word) + " is a number; name the features instead, joined by '|'";
    default: break;
  }
  if (parsed.feature >= features.size()) return "feature index " + std::to_string(parsed.feature) + " is out of range";
  return about_feature(parsed, features[parsed.feature]);
}

}  // namespace shadergen
