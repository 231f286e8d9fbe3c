#include "compile/feature_reads.h"

#include <set>

#include "base/closest_name.h"
#include "compile/source_scan.h"

namespace shadergen {

namespace {

std::string kind_phrase(FeatureKind kind) {
  return kind == FeatureKind::specialization ? "a specialization constant" : "a run-time branch";
}

// The message's hint: the closest identifier the sources use, when one is close enough.
std::string did_you_mean(const std::string& define, const SourceScan& scan) {
  std::vector<std::string> known;
  known.reserve(scan.identifiers.size());
  for (const auto& [name, at] : scan.identifiers) known.push_back(name);
  std::optional<std::string> meant = closest_name(define, known);
  return meant ? "; did you mean " + *meant + "?" : std::string();
}

void unread_defines(const DomainSpec& spec, const SourceScan& scan, Diagnostics& errors) {
  for (const RawFeature& f : spec.raw_features) {
    if (f.unread_allowed || scan.identifiers.count(f.define)) continue;
    errors.push_back(Diagnostic{Severity::error, spec.spec_path.string(), f.define_line, f.define_column,
                                "feature " + f.name + ": no source of its permutations reads its define " + f.define +
                                    did_you_mean(f.define, scan)});
  }
}

void conditionals_on_constants(const DomainSpec& spec, const SourceScan& scan, Diagnostics& errors) {
  std::set<std::string> reported;
  for (const ConditionalTest& test : scan.tests) {
    for (const RawFeature& f : spec.raw_features) {
      if (f.is_variant() || f.define != test.name || !reported.insert(f.name).second) continue;
      errors.push_back(make_error(test.at.file.string(), test.at.line,
                                  "feature " + f.name + " (define " + f.define + ") is " + kind_phrase(f.kind) + "; " +
                                      test.directive + " cannot test it: read it as an expression, e.g. if (" +
                                      f.define + ")"));
    }
  }
}

// A value-style boolean is defined in every permutation, as (1 == 1) or (0 == 1): `#ifdef`,
// `#ifndef` and `defined()` are then always true (or false), and the feature silently does
// nothing. A valued feature is always defined too, but it is never "off": guarding one with
// `#ifndef` for a default (uber/local_light.frag's LIGHT_TYPE) stays allowed.
bool tests_presence(const ConditionalTest& test) {
  return test.directive == "#ifdef" || test.directive == "#ifndef" || test.directive == "defined()";
}

void presence_tests_on_value_booleans(const DomainSpec& spec, const SourceScan& scan, Diagnostics& errors) {
  std::set<std::string> reported;
  for (const ConditionalTest& test : scan.tests) {
    if (!tests_presence(test)) continue;
    for (const RawFeature& f : spec.raw_features) {
      if (!f.is_variant() || f.valued() || f.define_style != DefineStyle::value) continue;
      if (f.define != test.name || !reported.insert(f.name).second) continue;
      errors.push_back(make_error(test.at.file.string(), test.at.line,
                                  "feature " + f.name + " (define " + f.define +
                                      ") is a value-style boolean, defined in every permutation as (1 == 1) or "
                                      "(0 == 1); " +
                                      test.directive + " is " + (test.directive == "#ifndef" ? "never" : "always") +
                                      " true: test its value, e.g. #if " + f.define + " or if (" + f.define + ")"));
    }
  }
}

}  // namespace

Status check_feature_reads(const DomainSpec& spec) {
  std::vector<std::filesystem::path> files{spec.uber.path};
  if (spec.program_vertex) files.push_back(spec.program_vertex->path);
  const SourceScan scan = scan_sources(files, spec.include_dirs);
  Diagnostics errors;
  unread_defines(spec, scan, errors);
  conditionals_on_constants(spec, scan, errors);
  presence_tests_on_value_booleans(spec, scan, errors);
  if (!errors.empty()) return errors;
  return Ok{};
}

}  // namespace shadergen
