// Feature kinds (variant, specialization, branch) as the spec states them: the spec's checks
// with their exact messages, the constant IDs, the declarations shadergen adds to a shader, and
// the checks on how the shaders read the features (an unread define, #ifdef on a constant).
#include <gtest/gtest.h>

#include <string>

#include "compile/feature_reads.h"
#include "shadergen/domain.h"
#include "shadergen/permutations.h"
#include "spec/kind_declarations.h"
#include "test_helpers.h"

namespace shadergen {
namespace {

// Line numbers in the expectations below refer to this text.
const std::string kBase = R"({
  "format": 1,
  "name": "kinds",
  "uber_shader": { "path": "kinds.frag", "stage": "fragment" },
  "raw": {
    "features": [
      { "name": "FOG", "bit": 0, "define": "HAS_FOG", "kind": "specialization" },
      { "name": "SOFT", "bit": 1, "define": "SOFT", "kind": "variant" },
      { "name": "TAPS", "bit": 2, "define": "TAPS", "values": [1, 4, 8], "kind": "specialization" },
      { "name": "SHADING", "bit": 4, "define": "SHADING", "values": ["UNLIT", "PBR"], "kind": "branch" }
    ],
    "impossible": [ { "when": "FOG && SHADING == UNLIT", "why": "rules may name any kind" } ]
  },
  "branch_block": { "set": 1, "binding": 2 },
  "optimised": {
    "bits": [ { "name": "X", "bit": 0, "when": "SOFT" } ],
    "variants": [ { "when": "X", "raw_features": ["SOFT"] } ]
  }
}
)";

DomainSpec parsed(const std::string& text) {
  auto result = parse_domain(text, "dir/spec.json");
  EXPECT_TRUE(result.ok()) << (result.ok() ? "" : result.errors().front().to_string());
  return result.ok() ? std::move(result).value() : DomainSpec{};
}

TEST(Kinds, BaseSpecReadsEachKind) {
  DomainSpec spec = parsed(kBase);
  ASSERT_EQ(spec.raw_features.size(), 4u);
  EXPECT_EQ(spec.raw_features[0].kind, FeatureKind::specialization);
  EXPECT_EQ(spec.raw_features[1].kind, FeatureKind::variant);
  EXPECT_EQ(spec.raw_features[3].kind, FeatureKind::branch);
  ASSERT_TRUE(spec.branch_block.has_value());
  EXPECT_EQ(spec.branch_block->set, 1u);
  EXPECT_EQ(spec.branch_block->binding, 2u);
  EXPECT_EQ(spec.variant_mask(), 0b10u);
}

TEST(Kinds, ConstantIdsArePinnedOrTheSmallestFreeInSpecOrder) {
  DomainSpec spec = parsed(kBase);
  EXPECT_EQ(spec.raw_features[0].constant_id, 0u);
  EXPECT_EQ(spec.raw_features[2].constant_id, 1u);
  // FOG unpinned after TAPS pins 0: FOG takes 1, the smallest free ID.
  spec = parsed(sgtest::replace_once(kBase, "\"values\": [1, 4, 8], \"kind\": \"specialization\"",
                                     "\"values\": [1, 4, 8], \"kind\": \"specialization\", \"constant_id\": 0"));
  EXPECT_EQ(spec.raw_features[2].constant_id, 0u);
  EXPECT_EQ(spec.raw_features[0].constant_id, 1u);
}

TEST(Kinds, OnlyVariantsMakeDefines) {
  DomainSpec spec = parsed(kBase);
  // Raw 0b11111 = FOG, SOFT, TAPS=8? (index 3 holds no value), SHADING=PBR: only SOFT is a define.
  EXPECT_EQ(raw_defines(spec, 0b10011u), (std::vector<std::string>{"SOFT"}));
  EXPECT_EQ(raw_defines(spec, 0b10001u), (std::vector<std::string>{}));
  DomainSpec valued =
      parsed(sgtest::replace_once(kBase, "\"format\": 1,", "\"format\": 1, \"define_style\": \"value\","));
  EXPECT_EQ(raw_defines(valued, 0u), (std::vector<std::string>{"SOFT=0"}));
  EXPECT_EQ(raw_defines(valued, 0b10u), (std::vector<std::string>{"SOFT=1"}));
}

// Turning the last branch into a variant is an edit of its "kind": the block left in the spec
// is a warning, and it is not declared (issue 51).
TEST(Kinds, ABlockWithoutABranchIsAWarningAndNotDeclared) {
  auto spec = parse_domain(
      sgtest::replace_once(kBase, "[\"UNLIT\", \"PBR\"], \"kind\": \"branch\"", "[\"UNLIT\", \"PBR\"]"), "spec.json");
  ASSERT_TRUE(spec.ok()) << spec.errors().front().to_string();
  EXPECT_FALSE(spec->branch_block.has_value());
  ASSERT_EQ(spec->warnings.size(), 1u);
  EXPECT_EQ(spec->warnings.front().to_string(),
            "spec.json:14:19: warning: branch_block: no feature is of kind branch, so no block is declared; remove "
            "it, or make a feature a branch");
  EXPECT_TRUE(parsed(kBase).warnings.empty());
}

// After a first error only the errors that still hold are reported: a misspelt kind or key
// leaves the features unread, and the block then says nothing about them (issue 51).
TEST(Kinds, AMisspeltKindOrKeyGivesOneErrorAndNoneAboutTheBlock) {
  for (const std::string& text : {sgtest::replace_once(kBase, "\"kind\": \"variant\"", "\"kind\": \"specialisation\""),
                                  sgtest::replace_once(kBase, "\"format\": 1", "\"formt\": 1"),
                                  sgtest::replace_once(kBase, "\"raw\": {", "\"raw\": { \"impossibel\": [],")}) {
    auto spec = parse_domain(text, "spec.json");
    ASSERT_FALSE(spec.ok());
    std::string all;
    for (const Diagnostic& d : spec.errors()) all += d.to_string() + "\n";
    EXPECT_EQ(spec.errors().size(), 1u) << all;
    EXPECT_FALSE(sgtest::contains(all, "no feature is of kind branch")) << all;
  }
}

class KindErrorTable : public ::testing::TestWithParam<sgtest::SpecErrorCase> {};

TEST_P(KindErrorTable, ExactDiagnostic) { EXPECT_EQ(sgtest::first_spec_error(GetParam().text), GetParam().expected); }

INSTANTIATE_TEST_SUITE_P(
    Cases, KindErrorTable,
    ::testing::Values(
        sgtest::SpecErrorCase{
            "unknown_kind", sgtest::replace_once(kBase, "\"kind\": \"variant\"", "\"kind\": \"dynamic\""),
            "spec.json:8:61: error: raw.features[1].kind: unknown kind \"dynamic\" (expected variant, "
            "specialization or branch)"},
        sgtest::SpecErrorCase{
            "constant_id_of_a_variant",
            sgtest::replace_once(kBase, "\"kind\": \"variant\"", "\"kind\": \"variant\", \"constant_id\": 3"),
            "spec.json:8:87: error: raw.features[1].constant_id: only a specialization feature has a "
            "constant_id (this one is a variant)"},
        sgtest::SpecErrorCase{
            "constant_id_twice",
            sgtest::replace_once(sgtest::replace_once(kBase, "\"HAS_FOG\", \"kind\": \"specialization\"",
                                                      "\"HAS_FOG\", \"kind\": \"specialization\", \"constant_id\": 5"),
                                 "[1, 4, 8], \"kind\": \"specialization\"",
                                 "[1, 4, 8], \"kind\": \"specialization\", \"constant_id\": 5"),
            "spec.json:9:115: error: raw.features[2].constant_id: constant_id 5 is already taken by feature "
            "FOG"},
        sgtest::SpecErrorCase{
            "branch_without_its_block",
            sgtest::replace_once(kBase, "\"branch_block\": { \"set\": 1, \"binding\": 2 },", ""),
            "spec.json:1:1: error: spec: feature SHADING is a run-time branch: its value is read from a "
            "uniform block, so the spec needs \"branch_block\": {\"set\": S, \"binding\": B}"},
        sgtest::SpecErrorCase{"optimised_bit_on_a_constant",
                              sgtest::replace_once(kBase, "\"when\": \"SOFT\"", "\"when\": \"SOFT || FOG\""),
                              "spec.json:16:48: error: optimised.bits[0].when: optimised bit X names feature FOG, a "
                              "specialization constant: the collapse is over variant features only"},
        sgtest::SpecErrorCase{
            "variant_compiles_a_branch",
            sgtest::replace_once(kBase, "\"raw_features\": [\"SOFT\"]",
                                 "\"raw_features\": [\"SOFT\", \"SHADING=PBR\"]"),
            "spec.json:17:59: error: optimised.variants[0].raw_features[1]: SHADING is a run-time branch: a "
            "variant compiles variant features only (its value travels beside the optimised ID)"},
        sgtest::SpecErrorCase{
            "unknown_define_style",
            sgtest::replace_once(kBase, "\"format\": 1,", "\"format\": 1, \"define_style\": \"always\","),
            "spec.json:2:32: error: define_style: unknown define style \"always\" (expected presence or value)"},
        sgtest::SpecErrorCase{
            "unread_not_allowed",
            sgtest::replace_once(kBase, "\"kind\": \"variant\"", "\"kind\": \"variant\", \"unread\": true"),
            "spec.json:8:82: error: raw.features[1].unread: expected \"allowed\", found a boolean"},
        sgtest::SpecErrorCase{
            "identifier_value_two_indices",
            sgtest::replace_once(kBase, "\"values\": [1, 4, 8]", "\"values\": [\"LOW\", \"PBR\", \"UNLIT\"]"),
            "spec.json:10:48: error: raw.features[3].values: value UNLIT is declared to the shader as 0 for "
            "SHADING and as 2 for TAPS"}));

TEST(KindDeclarations, SpecializationConstantsIdentifierValuesAndTheBranchBlock) {
  DomainSpec spec = parsed(kBase);
  KindDeclarations kinds = kind_declarations(spec);
  EXPECT_EQ(kinds.macros, "");
  EXPECT_EQ(kinds.declarations,
            "const int UNLIT = 0;\n"
            "const int PBR = 1;\n"
            "layout(constant_id = 0) const bool HAS_FOG = false;\n"
            "layout(constant_id = 1) const int TAPS = 1;\n"
            "layout(std140, set = 1, binding = 2) uniform ShadergenBranchBlock {\n"
            "  uint SHADING;\n"
            "} shadergen_branch;\n"
            "#define SHADING int(shadergen_branch.SHADING)\n");
}

TEST(KindDeclarations, ValueStyleVariantsDefineTheirIdentifiersAndReadableBooleans) {
  DomainSpec spec = parsed(sgtest::replace_once(
      sgtest::replace_once(sgtest::replace_once(kBase, "\"format\": 1,", "\"format\": 1, \"define_style\": \"value\","),
                           "[\"UNLIT\", \"PBR\"], \"kind\": \"branch\"", "[\"UNLIT\", \"PBR\"]"),
      "\"branch_block\": { \"set\": 1, \"binding\": 2 },", ""));
  KindDeclarations kinds = kind_declarations(spec);
  EXPECT_EQ(kinds.macros, "#define UNLIT 0\n#define PBR 1\n");
  EXPECT_EQ(boolean_value_defines({"SOFT=1", "SHADING=PBR"}, kinds),
            (std::vector<std::string>{"SOFT=(1 == 1)", "SHADING=PBR"}));
  EXPECT_EQ(boolean_value_defines({"SOFT=0"}, kinds), (std::vector<std::string>{"SOFT=(0 == 1)"}));
}

TEST(KindDeclarations, InsertedAfterVersionWithTheFilesLineNumbersKept) {
  EXPECT_EQ(insert_declarations("// header\n#version 450\nvoid main() {}\n", "const int A = 1;\n"),
            "// header\n#version 450\nconst int A = 1;\n#line 3\nvoid main() {}\n");
  EXPECT_EQ(insert_declarations("/* a\n b */\n  #  version 460\nx\n", "D\n"),
            "/* a\n b */\n  #  version 460\nD\n#line 4\nx\n");
  EXPECT_EQ(insert_declarations("void main() {}\n", "D\n"), "D\n#line 1\nvoid main() {}\n");
  EXPECT_EQ(insert_declarations("#version 450\nx\n", ""), "#version 450\nx\n");
}

// The permuted shader and an include, written to a temporary folder with the spec.
class FeatureReads : public ::testing::Test {
 protected:
  Status check(const std::string& spec_text, const std::string& shader, const std::string& include = "") {
    sgtest::write_file(dir_ / "kinds.frag", shader);
    sgtest::write_file(dir_ / "common.glsl", include);
    auto spec = parse_domain(spec_text, dir_ / "spec.json");
    EXPECT_TRUE(spec.ok());
    if (!spec.ok()) return std::move(spec).take_errors();
    return check_feature_reads(*spec);
  }
  static std::string first(const Status& s) { return s.ok() ? "(none)" : s.errors().front().to_string(); }
  sgtest::TempDir dir_{"feature_reads"};
};

const std::string kReadsAll =
    "#version 450\n#include \"common.glsl\"\nvoid main() {\n  if (HAS_FOG && SOFT) {}\n  int t = TAPS + SHADING;\n}\n";

TEST_F(FeatureReads, EveryDefineReadAsAnExpressionPasses) { EXPECT_EQ(first(check(kBase, kReadsAll)), "(none)"); }

TEST_F(FeatureReads, AMisspeltDefineIsNamedWithTheClosestIdentifierTheSourcesUse) {
  std::string spec = sgtest::replace_once(kBase, "\"HAS_FOG\"", "\"HAS_FOGG\"");
  EXPECT_EQ(first(check(spec, kReadsAll)),
            (dir_ / "spec.json").string() +
                ":7:44: error: feature FOG: no source of its permutations reads its define HAS_FOGG; did you mean "
                "HAS_FOG?");
}

TEST_F(FeatureReads, ADefineReadOnlyInAnIncludeIsRead) {
  EXPECT_EQ(first(check(kBase, "#version 450\n#include \"common.glsl\"\nvoid main() { int t = TAPS + SHADING; }\n",
                        "// FOG and SOFT\nbool f() { return HAS_FOG || SOFT; }\n")),
            "(none)");
}

TEST_F(FeatureReads, ADefineNamedOnlyInACommentIsUnreadUnlessAllowed) {
  const std::string shader = "#version 450\n// SOFT\nvoid main() { int t = TAPS + SHADING; bool f = HAS_FOG; }\n";
  EXPECT_EQ(first(check(kBase, shader)),
            (dir_ / "spec.json").string() +
                ":8:45: error: feature SOFT: no source of its permutations reads its define SOFT");
  EXPECT_EQ(first(check(
                sgtest::replace_once(kBase, "\"kind\": \"variant\"", "\"kind\": \"variant\", \"unread\": \"allowed\""),
                shader)),
            "(none)");
}

TEST_F(FeatureReads, IfdefOnASpecializationConstantIsAnErrorAtItsLine) {
  EXPECT_EQ(first(check(kBase, kReadsAll + "#ifdef HAS_FOG\n#endif\n")),
            (dir_ / "kinds.frag").string() +
                ":7: error: feature FOG (define HAS_FOG) is a specialization constant; #ifdef cannot test it: read "
                "it as an expression, e.g. if (HAS_FOG)");
}

TEST_F(FeatureReads, IfOrDefinedOnABranchInAnIncludeIsAnErrorThere) {
  EXPECT_EQ(first(check(kBase, kReadsAll, "\n#if SHADING == PBR\n#endif\n")),
            (dir_ / "common.glsl").string() +
                ":2: error: feature SHADING (define SHADING) is a run-time branch; #if cannot test it: read it as an "
                "expression, e.g. if (SHADING)");
  EXPECT_EQ(first(check(kBase, kReadsAll, "#if defined(TAPS) && 1\n#endif\n")),
            (dir_ / "common.glsl").string() +
                ":1: error: feature TAPS (define TAPS) is a specialization constant; defined() cannot test it: read "
                "it as an expression, e.g. if (TAPS)");
}

TEST_F(FeatureReads, AVariantMayBeTestedByThePreprocessor) {
  EXPECT_EQ(first(check(kBase, kReadsAll + "#ifdef SOFT\n#endif\n")), "(none)");
}

// A value-style boolean is defined in every permutation ((1 == 1) or (0 == 1)): a presence test
// on it never changes, so the feature silently did nothing (issue 51: 14 of 19 features gone).
TEST_F(FeatureReads, PresenceTestsOnAValueStyleBooleanAreAnErrorAtTheirLine) {
  const std::string spec = sgtest::replace_once(kBase, "\"kind\": \"variant\"", "\"define_style\": \"value\"");
  const std::string at = (dir_ / "kinds.frag").string() + ":7: error: feature SOFT (define SOFT) is a value-style ";
  EXPECT_EQ(first(check(spec, kReadsAll + "#ifdef SOFT\n#endif\n")),
            at + "boolean, defined in every permutation as (1 == 1) or (0 == 1); #ifdef is always true: test its "
                 "value, e.g. #if SOFT or if (SOFT)");
  EXPECT_EQ(first(check(spec, kReadsAll + "#ifndef SOFT\n#endif\n")),
            at + "boolean, defined in every permutation as (1 == 1) or (0 == 1); #ifndef is never true: test its "
                 "value, e.g. #if SOFT or if (SOFT)");
  EXPECT_EQ(first(check(spec, kReadsAll + "#if 1 && defined(SOFT)\n#endif\n")),
            at + "boolean, defined in every permutation as (1 == 1) or (0 == 1); defined() is always true: test its "
                 "value, e.g. #if SOFT or if (SOFT)");
  EXPECT_EQ(first(check(spec, kReadsAll + "#if SOFT\n#endif\n")), "(none)") << "#if reads the value";
}

// A valued feature is never "off", so a guard that gives it a default stays allowed (as
// uber/local_light.frag guards LIGHT_TYPE).
TEST_F(FeatureReads, AValuedValueStyleVariantMayBeGuarded) {
  const std::string spec =
      sgtest::replace_once(sgtest::replace_once(kBase, "\"format\": 1,", "\"format\": 1, \"define_style\": \"value\","),
                           "\"values\": [1, 4, 8], \"kind\": \"specialization\"", "\"values\": [1, 4, 8]");
  EXPECT_EQ(first(check(spec, kReadsAll + "#ifndef TAPS\n#define TAPS 1\n#endif\n")), "(none)");
}

}  // namespace
}  // namespace shadergen
