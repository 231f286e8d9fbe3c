// The "ignore" form of the collapse: "optimised": {"ignore": [{"feature", "when"}]}. The
// optimised IDs are the distinct combinations of variant features the raw IDs reach once the
// ignored features are dropped, numbered by their smallest raw ID; no unreachable one exists.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "shadergen/domain.h"
#include "shadergen/permutations.h"
#include "test_helpers.h"

namespace shadergen {
namespace {

// The adopter's material: "unlit ignores LIGHT_COUNT". Line numbers below refer to this text.
const std::string kMaterial = R"({
  "format": 1,
  "name": "material",
  "uber_shader": { "path": "m.frag" },
  "raw": {
    "features": [
      { "name": "SHADING", "bit": 0, "define": "SHADING", "values": ["UNLIT", "PBR"] },
      { "name": "LIGHT_COUNT", "bit": 1, "define": "LIGHT_COUNT", "values": [1, 2, 4] },
      { "name": "NORMAL_MAP", "bit": 3, "define": "NORMAL_MAP" },
      { "name": "FOG", "bit": 4, "define": "FOG", "kind": "specialization" }
    ]
  },
  "optimised": { "ignore": [ { "feature": "LIGHT_COUNT", "when": "SHADING == UNLIT" } ] }
}
)";

PermutationPlan expanded(const std::string& text) {
  auto spec = parse_domain(text, "spec.json");
  EXPECT_TRUE(spec.ok()) << (spec.ok() ? "" : spec.errors().front().to_string());
  if (!spec.ok()) return {};
  auto plan = expand(*spec);
  EXPECT_TRUE(plan.ok()) << (plan.ok() ? "" : plan.errors().front().to_string());
  return plan.ok() ? std::move(plan).value() : PermutationPlan{};
}

TEST(IgnoreCollapse, TheOptimisedIdsAreTheReachableCombinationsBySmallestRawId) {
  PermutationPlan plan = expanded(kMaterial);
  // Unlit x normal map, and pbr x 3 light counts x normal map: 2 + 6, never the 12 a bit per
  // feature would give. FOG, a specialization constant, takes no optimised ID of its own.
  ASSERT_EQ(plan.optimised.size(), 8u);
  std::vector<std::uint32_t> first_raw;
  for (const OptimisedPermutation& o : plan.optimised) first_raw.push_back(o.raw_equivalent);
  EXPECT_EQ(first_raw, (std::vector<std::uint32_t>{0, 1, 3, 5, 8, 9, 11, 13}));
  EXPECT_EQ(plan.optimised[0].defines, (std::vector<std::string>{"SHADING=UNLIT", "LIGHT_COUNT=1"}));
  // Raw 2 (unlit, 2 lights) and raw 16 + 4 (unlit, 4 lights, fog) draw with optimised 0.
  EXPECT_EQ(plan.raw[2].optimised, 0u);
  EXPECT_EQ(plan.raw[20].optimised, 0u);
  EXPECT_EQ(plan.raw[21].optimised, 3u);  // pbr, 4 lights, fog
  EXPECT_EQ(plan.optimised[0].raw_mapped, 6u);
  for (const OptimisedPermutation& o : plan.optimised) EXPECT_GT(o.raw_mapped, 0u) << o.id;
}

TEST(IgnoreCollapse, WithNothingIgnoredEachVariantCombinationIsOneOptimisedId) {
  PermutationPlan plan =
      expanded(sgtest::replace_once(kMaterial, R"({ "feature": "LIGHT_COUNT", "when": "SHADING == UNLIT" })", ""));
  EXPECT_EQ(plan.optimised.size(), 12u);  // 2 x 3 x 2; FOG's bit is dropped
  EXPECT_EQ(plan.raw[16].optimised, plan.raw[0].optimised);
}

class IgnoreErrorTable : public ::testing::TestWithParam<sgtest::SpecErrorCase> {};

TEST_P(IgnoreErrorTable, ExactDiagnostic) { EXPECT_EQ(sgtest::first_spec_error(GetParam().text), GetParam().expected); }

INSTANTIATE_TEST_SUITE_P(
    Cases, IgnoreErrorTable,
    ::testing::Values(
        sgtest::SpecErrorCase{
            "both_forms",
            sgtest::replace_once(kMaterial, "\"optimised\": { \"ignore\"", "\"optimised\": { \"bits\": [], \"ignore\""),
            "spec.json:13:40: error: optimised.ignore: \"ignore\" replaces \"bits\" and \"variants\": a collapse "
            "takes one form or the other"},
        sgtest::SpecErrorCase{
            "unknown_feature",
            sgtest::replace_once(kMaterial, "\"feature\": \"LIGHT_COUNT\"", "\"feature\": \"LIGHTS\""),
            "spec.json:13:43: error: optimised.ignore[0].feature: unknown raw feature \"LIGHTS\""},
        sgtest::SpecErrorCase{
            "a_constant", sgtest::replace_once(kMaterial, "\"feature\": \"LIGHT_COUNT\"", "\"feature\": \"FOG\""),
            "spec.json:13:43: error: optimised.ignore[0].feature: FOG is a specialization constant: it is never "
            "compiled in, so an optimised shader has nothing to leave out"},
        sgtest::SpecErrorCase{
            "bad_rule", sgtest::replace_once(kMaterial, "\"SHADING == UNLIT\"", "\"SHADING == MATTE\""),
            "spec.json:13:66: error: optimised.ignore[0].when: 'SHADING' has no value MATTE (values: UNLIT, "
            "PBR) in \"SHADING == MATTE\" at column 12 (rules here name raw features)"},
        // The optimised ID comes from the table: a rule on a pipeline-time value would make the
        // program drawn depend on it (issue 51).
        sgtest::SpecErrorCase{
            "a_rule_on_a_constant",
            sgtest::replace_once(kMaterial, "\"SHADING == UNLIT\"", "\"SHADING == UNLIT || FOG\""),
            "spec.json:13:66: error: optimised.ignore[0].when: the rule names feature FOG, a specialization "
            "constant: which optimised shader a raw ID draws cannot depend on a value set at run time (the "
            "collapse is over variant features only)"}));

}  // namespace
}  // namespace shadergen
