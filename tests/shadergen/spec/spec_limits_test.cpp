// The parser's bounds (docs/spec-format.md, "Limits"): each one at its limit is accepted and one
// past it is rejected with an exact message that names the file, the place and the limit.
// They exist so that no input can make the parser crash, recurse or allocate without bound.
#include <gtest/gtest.h>

#include <string>

#include "shadergen/domain.h"
#include "shadergen/expression.h"
#include "shadergen/permutations.h"
#include "spec/json.h"
#include "test_helpers.h"

namespace shadergen {
namespace {

std::string repeat(const std::string& item, std::size_t count, const std::string& separator = ", ") {
  std::string out;
  for (std::size_t i = 0; i < count; ++i) out += (i ? separator : "") + item;
  return out;
}

// A valid spec with the given list lengths and optimised rule. Each list is on a line of its
// own, so the expected line numbers below stay fixed: include_dirs 4, impossible 7, the
// optimised rule 10, variants 11.
struct Shape {
  std::size_t include_dirs = 0;
  std::size_t impossible = 1;
  std::size_t variants = 1;
  std::string rule = "A || B";
};

std::string spec_text(const Shape& shape) {
  return "{\n"
         "  \"name\": \"limits\",\n"
         "  \"uber_shader\": { \"path\": \"u.frag\", \"stage\": \"fragment\" },\n"
         "  \"include_dirs\": [" +
         repeat("\"inc\"", shape.include_dirs) +
         "],\n"
         "  \"raw\": {\n"
         "    \"features\": [ { \"name\": \"A\", \"bit\": 0, \"define\": \"HAS_A\" }, "
         "{ \"name\": \"B\", \"bit\": 1, \"define\": \"HAS_B\" } ],\n"
         "    \"impossible\": [" +
         repeat("{ \"when\": \"A && B\" }", shape.impossible) +
         "]\n"
         "  },\n"
         "  \"optimised\": {\n"
         "    \"bits\": [ { \"name\": \"X\", \"bit\": 0, \"when\": \"" +
         shape.rule +
         "\" } ],\n"
         "    \"variants\": [" +
         repeat("{ \"when\": \"X\", \"raw_features\": [\"A\"] }", shape.variants) +
         "]\n"
         "  }\n"
         "}\n";
}

// "A || A || ... A" padded with spaces to exactly `length` characters (length >= 1).
std::string rule_of_length(std::size_t length) {
  std::string rule = "A" + repeat(" || A", (length - 1) / 5, "");
  return rule + std::string(length - rule.size(), ' ');
}

// An array holding `count` zeros: count + 1 JSON values in all.
std::string array_of_zeros(std::size_t count) { return "[" + repeat("0", count, ",") + "]"; }

struct LimitCase {
  const char* name;
  std::string text;
  std::string expected;
};

void PrintTo(const LimitCase& c, std::ostream* os) { *os << c.name; }

class SpecLimitTable : public ::testing::TestWithParam<LimitCase> {};

TEST_P(SpecLimitTable, ExactDiagnostic) { EXPECT_EQ(sgtest::first_spec_error(GetParam().text), GetParam().expected); }

INSTANTIATE_TEST_SUITE_P(
    Limits, SpecLimitTable,
    ::testing::Values(
        LimitCase{"base_is_valid", spec_text({}), "(no error)"},
        LimitCase{"include_dirs_at_limit", spec_text({.include_dirs = kMaxIncludeDirs}), "(no error)"},
        LimitCase{"include_dirs_over_limit", spec_text({.include_dirs = kMaxIncludeDirs + 1}),
                  "spec.json:4:19: error: include_dirs: more than 64 include folders (found 65)"},
        LimitCase{"impossible_at_limit", spec_text({.impossible = kMaxImpossibleRules}), "(no error)"},
        LimitCase{"impossible_over_limit", spec_text({.impossible = kMaxImpossibleRules + 1}),
                  "spec.json:7:19: error: raw.impossible: more than 64 rules (found 65)"},
        LimitCase{"variants_at_limit", spec_text({.variants = kMaxVariants}), "(no error)"},
        LimitCase{"variants_over_limit", spec_text({.variants = kMaxVariants + 1}),
                  "spec.json:11:17: error: optimised.variants: more than 256 variants (found 257)"},
        LimitCase{"rule_at_limit", spec_text({.rule = rule_of_length(kMaxExpressionLength)}), "(no error)"},
        // The message quotes only the start of an over-long rule.
        LimitCase{"rule_over_limit", spec_text({.rule = rule_of_length(kMaxExpressionLength + 1)}),
                  "spec.json:10:48: error: optimised.bits[0].when: rule is 1025 characters long; the limit is 1024 "
                  "in \"A || A || A || A || A || A || A || A || ...\" at column 1025 (rules here name raw features)"},
        // At the value limit the parser reaches the domain checks; one more value stops it.
        LimitCase{"json_values_at_limit", array_of_zeros(json::kMaxJsonValues - 1),
                  "spec.json:1:1: error: spec: the spec must be a JSON object"},
        LimitCase{"json_values_over_limit", array_of_zeros(json::kMaxJsonValues),
                  "spec.json:1:131072: error: more than 65536 JSON values"}),
    [](const ::testing::TestParamInfo<LimitCase>& param) { return std::string(param.param.name); });

TEST(SpecLimits, ProblemsBeyondTheLimitAreCountedNotListed) {
  // Every unknown key is a problem of its own; 60 of them exceed the list's bound.
  std::string text = "{ ";
  for (int i = 0; i < 60; ++i) text += "\"unknown" + std::to_string(i) + "\": 0, ";
  text += "\"name\": \"x\" }";
  auto result = parse_domain(text, "spec.json");
  ASSERT_FALSE(result.ok());
  ASSERT_EQ(result.errors().size(), kMaxSpecErrors + 1);
  EXPECT_EQ(result.errors().back().to_string(), "spec.json: error: more than 50 problems; the rest are not reported");
}

// 20 raw bits (enumerated) and 64 impossible rules of about 1,000 characters: 2^20 raw IDs times
// 64 long rules took 132 s before the bound; now expansion refuses it at once. A rule half as
// long for 2^18 IDs is well inside it.
std::string long_rules_spec(int features, std::size_t rule_terms) {
  std::string list;
  for (int i = 0; i < features; ++i)
    list += std::string(i ? ", " : "") + "{ \"name\": \"F" + std::to_string(i) + "\", \"bit\": " + std::to_string(i) +
            ", \"define\": \"D" + std::to_string(i) + "\" }";
  std::string rules;
  for (int i = 0; i < 64; ++i)
    rules += std::string(i ? ", " : "") + "{ \"when\": \"" +
             repeat("F3 && F" + std::to_string(i % features), rule_terms, " && ") + "\" }";
  return "{ \"name\": \"work\", \"uber_shader\": { \"path\": \"u.frag\" }, \"raw\": { \"features\": [" + list +
         "], \"impossible\": [" + rules + "] } }";
}

TEST(SpecLimits, ExpansionWorkIsBounded) {
  auto spec = parse_domain(long_rules_spec(20, 60), "spec.json");
  ASSERT_TRUE(spec.ok()) << spec.errors().front().to_string();
  auto plan = expand(*spec);
  ASSERT_FALSE(plan.ok());
  EXPECT_EQ(plan.errors().front().to_string(),
            "spec.json: error: expanding the domain would evaluate its rules for 1048576 raw IDs and 0 optimised IDs, "
            "50004492288 rule characters in all; the limit is 4294967296: shorten the impossible, optimised-bit and "
            "variant rules, or build fewer raw IDs");
  auto smaller = parse_domain(long_rules_spec(12, 60), "spec.json");
  ASSERT_TRUE(smaller.ok());
  EXPECT_TRUE(expand(*smaller).ok());
}

}  // namespace
}  // namespace shadergen
