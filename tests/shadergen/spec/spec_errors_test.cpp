// Malformed specs: each case breaks one thing in a small valid spec and asserts the exact
// diagnostic, which must name the file, the line and column, the key path and the problem.
#include <gtest/gtest.h>

#include <string>

#include "shadergen/domain.h"
#include "shadergen/permutations.h"
#include "spec/json.h"
#include "test_helpers.h"

namespace shadergen {
namespace {

// Line numbers in the expectations below refer to this text.
const std::string kBase = R"({
  "format": 1,
  "name": "tiny",
  "uber_shader": { "path": "tiny.frag", "stage": "fragment" },
  "raw": {
    "features": [
      { "name": "A", "bit": 0, "define": "HAS_A" },
      { "name": "B", "bit": 1, "define": "HAS_B" },
      { "name": "C", "bit": 2, "define": "HAS_C" }
    ],
    "impossible": [ { "when": "A && B", "why": "never both" } ]
  },
  "optimised": {
    "bits": [ { "name": "X", "bit": 0, "when": "A || C" } ],
    "variants": [ { "when": "X", "raw_features": ["A", "C"] } ]
  }
}
)";

TEST(SpecErrors, BaseSpecIsValid) {
  auto result = parse_domain(kBase, "dir/spec.json");
  ASSERT_TRUE(result.ok()) << result.errors().front().to_string();
  EXPECT_EQ(result->uber.path, std::filesystem::path("dir/tiny.frag"));
  EXPECT_EQ(result->raw_space(), 8u);
}

class SpecErrorTable : public ::testing::TestWithParam<sgtest::SpecErrorCase> {};

TEST_P(SpecErrorTable, ExactDiagnostic) { EXPECT_EQ(sgtest::first_spec_error(GetParam().text), GetParam().expected); }

INSTANTIATE_TEST_SUITE_P(
    Cases, SpecErrorTable,
    ::testing::Values(
        sgtest::SpecErrorCase{
            "truncated", kBase.substr(0, kBase.find("\"impossible\"")),
            "spec.json:11:5: error: unexpected end of file inside an object (the spec is truncated?)"},
        sgtest::SpecErrorCase{
            "unknown_name_in_rule", sgtest::replace_once(kBase, "\"A && B\"", "\"A && D\""),
            "spec.json:11:31: error: raw.impossible[0].when: unknown name 'D' (known: A, B, C) in \"A && D\" "
            "at column 6 (rules here name raw features)"},
        sgtest::SpecErrorCase{"bit_collision", sgtest::replace_once(kBase, "\"C\", \"bit\": 2", "\"C\", \"bit\": 1"),
                              "spec.json:9:29: error: raw.features[2].bit: bit 1 of C collides with feature B"},
        sgtest::SpecErrorCase{
            "duplicate_define", sgtest::replace_once(kBase, "\"HAS_C\"", "\"HAS_A\""),
            "spec.json:9:42: error: raw.features[2].define: define HAS_A is already used by feature A"},
        sgtest::SpecErrorCase{
            "unknown_key", sgtest::replace_once(kBase, "\"format\": 1", "\"formats\": 1"),
            "spec.json:2:14: error: spec: unknown key \"formats\" (expected one of: format, name, description, "
            "uber_shader, uber_shaders, program, include_dirs, target_env, layout, strip_debug, defines, companions, "
            "raw, "
            "optimised, compile, variants_file, define_style, branch_block)"},
        sgtest::SpecErrorCase{
            "bit_out_of_range", sgtest::replace_once(kBase, "\"C\", \"bit\": 2", "\"C\", \"bit\": 3"),
            "spec.json:9:29: error: raw.features[2].bit: bit must be an integer from 0 to 2, found 3"},
        // Once undefined behaviour (a double far outside int64 converted before the range test).
        sgtest::SpecErrorCase{
            "bit_huge", sgtest::replace_once(kBase, "\"C\", \"bit\": 2", "\"C\", \"bit\": 1e300"),
            "spec.json:9:29: error: raw.features[2].bit: bit must be an integer from 0 to 2, found 1e+300"},
        sgtest::SpecErrorCase{"wrong_type",
                              sgtest::replace_once(kBase, "\"bit\": 0, \"define\"", "\"bit\": \"0\", \"define\""),
                              "spec.json:7:29: error: raw.features[0].bit: expected a number, found a string"},
        sgtest::SpecErrorCase{
            "rule_syntax", sgtest::replace_once(kBase, "\"A || C\"", "\"A || || C\""),
            "spec.json:14:48: error: optimised.bits[0].when: expected a feature name, '!' or '(' but found "
            "'|' in \"A || || C\" at column 6 (rules here name raw features)"},
        sgtest::SpecErrorCase{
            "optimised_rule_names_raw_bits", sgtest::replace_once(kBase, "{ \"when\": \"X\"", "{ \"when\": \"A\""),
            "spec.json:15:29: error: optimised.variants[0].when: unknown name 'A' (known: X) in \"A\" at "
            "column 1 (rules here name optimised bits)"},
        sgtest::SpecErrorCase{
            "unknown_stage", sgtest::replace_once(kBase, "\"fragment\"", "\"pixel\""),
            "spec.json:4:50: error: uber_shader.stage: unknown stage \"pixel\" (expected one of vertex, "
            "tess_control, tess_evaluation, geometry, fragment, compute, task, mesh, ray_generation, any_hit, "
            "closest_hit, miss, intersection, callable, or .vert .tesc .tese .geom .frag .comp .task .mesh .rgen "
            ".rahit .rchit .rmiss .rint .rcall without the dot)"},
        sgtest::SpecErrorCase{
            "no_stage_and_an_extension_that_names_none",
            sgtest::replace_once(kBase, "{ \"path\": \"tiny.frag\", \"stage\": \"fragment\" }",
                                 "{ \"path\": \"tiny.glsl\" }"),
            "spec.json:4:18: error: uber_shader: missing \"stage\", and the extension of \"tiny.glsl\" names none "
            "(one of .vert .tesc .tese .geom .frag .comp .task .mesh .rgen .rahit .rchit .rmiss .rint .rcall does)"},
        sgtest::SpecErrorCase{"missing_name", sgtest::replace_once(kBase, "\"name\": \"tiny\",", ""),
                              "spec.json:1:1: error: spec: missing \"name\""},
        sgtest::SpecErrorCase{"not_an_object", "[1, 2]\n",
                              "spec.json:1:1: error: spec: the spec must be a JSON object"},
        sgtest::SpecErrorCase{"trailing_comma", sgtest::replace_once(kBase, "\"never both\" }", "\"never both\", }"),
                              "spec.json:11:60: error: trailing comma before '}' (JSON allows none: remove it)"},
        // RFC 8259 text is UTF-8: a Latin-1 "é" (one byte 0xE9) is rejected where it starts.
        sgtest::SpecErrorCase{"latin1_byte_in_a_string", sgtest::replace_once(kBase, "\"tiny\",", "\"tin\xE9\","),
                              "spec.json:3:15: error: invalid UTF-8 in a string"},
        // A leading byte order mark is skipped, and columns count from after it.
        sgtest::SpecErrorCase{"byte_order_mark_then_an_error", "\xEF\xBB\xBF{ \"format\": 1, }",
                              "spec.json:1:14: error: trailing comma before '}' (JSON allows none: remove it)"},
        sgtest::SpecErrorCase{"nesting_limit", std::string(40, '[') + std::string(40, ']'),
                              "spec.json:1:33: error: nesting deeper than 32 levels"},
        sgtest::SpecErrorCase{
            "define_value_not_a_string",
            sgtest::replace_once(kBase, "\"format\": 1,", "\"format\": 1, \"defines\": { \"N\": 4 },"),
            "spec.json:2:34: error: defines.N: expected a string value, found a number (write \"N\": \"1\")"},
        sgtest::SpecErrorCase{
            "define_name_not_an_identifier",
            sgtest::replace_once(kBase, "\"format\": 1,", "\"format\": 1, \"defines\": { \"A-B\": \"1\" },"),
            "spec.json:2:36: error: defines.A-B: \"A-B\" is not an identifier ([A-Za-z_][A-Za-z0-9_]*, at most 64)"},
        sgtest::SpecErrorCase{
            "define_name_reserved",
            sgtest::replace_once(kBase, "\"format\": 1,", "\"format\": 1, \"defines\": { \"GL_X\": \"1\" },"),
            "spec.json:2:37: error: defines.GL_X: \"GL_X\" is reserved by GLSL (a GL_ prefix or a double "
            "underscore)"},
        sgtest::SpecErrorCase{
            "define_value_two_lines",
            sgtest::replace_once(kBase, "\"format\": 1,", "\"format\": 1, \"defines\": { \"X\": \"1\\n2\" },"),
            "spec.json:2:34: error: defines.X: the value holds a line break or another control character; it "
            "must fit on the #define line"},
        sgtest::SpecErrorCase{
            "define_of_a_feature",
            sgtest::replace_once(kBase, "\"format\": 1,", "\"format\": 1, \"defines\": { \"HAS_B\": \"1\" },"),
            "spec.json:2:38: error: defines.HAS_B: HAS_B is the define of raw feature B; a fixed define cannot "
            "also be a feature"},
        sgtest::SpecErrorCase{"defines_not_an_object",
                              sgtest::replace_once(kBase, "\"format\": 1,", "\"format\": 1, \"defines\": [\"X\"],"),
                              "spec.json:2:27: error: spec.defines: expected an object, found an array"},
        sgtest::SpecErrorCase{
            "values_duplicate",
            sgtest::replace_once(kBase, "\"define\": \"HAS_C\"", "\"define\": \"HAS_C\", \"values\": [1, 2, 1]"),
            "spec.json:9:68: error: raw.features[2].values[2]: value 1 is listed twice"},
        sgtest::SpecErrorCase{
            "value_not_integer_or_identifier",
            sgtest::replace_once(kBase, "\"define\": \"HAS_C\"", "\"define\": \"HAS_C\", \"values\": [1, 2.5]"),
            "spec.json:9:65: error: raw.features[2].values[1]: expected an integer or an identifier, found 2.5"},
        sgtest::SpecErrorCase{
            "value_not_identifier",
            sgtest::replace_once(kBase, "\"define\": \"HAS_C\"", "\"define\": \"HAS_C\", \"values\": [\"a-b\", \"c\"]"),
            "spec.json:9:62: error: raw.features[2].values[0]: expected an integer or an identifier, found \"a-b\""},
        sgtest::SpecErrorCase{
            "one_value", sgtest::replace_once(kBase, "\"define\": \"HAS_C\"", "\"define\": \"HAS_C\", \"values\": [1]"),
            "spec.json:9:61: error: raw.features[2].values: a valued feature has 2 to 256 values, found 1"},
        sgtest::SpecErrorCase{
            "boolean_compared_with_number", sgtest::replace_once(kBase, "\"A && B\"", "\"A == 1\""),
            "spec.json:11:31: error: raw.impossible[0].when: 'A' is a boolean feature; it cannot be compared "
            "with a number (write A or !A) in \"A == 1\" at column 1 (rules here name raw features)"},
        sgtest::SpecErrorCase{
            "unknown_value",
            sgtest::replace_once(sgtest::replace_once(kBase, "\"define\": \"HAS_C\"",
                                                      "\"define\": \"HAS_C\", \"values\": [0, 1, 2]"),
                                 "\"A && B\"", "\"C == 3\""),
            "spec.json:11:31: error: raw.impossible[0].when: 'C' has no value 3 (values: 0, 1, 2) in \"C == 3\" at "
            "column 6 (rules here name raw features)"},
        sgtest::SpecErrorCase{
            "order_on_identifiers",
            sgtest::replace_once(sgtest::replace_once(kBase, "\"define\": \"HAS_C\"",
                                                      "\"define\": \"HAS_C\", \"values\": [\"LOW\", \"HIGH\"]"),
                                 "\"A && B\"", "\"C >= HIGH\""),
            "spec.json:11:31: error: raw.impossible[0].when: '>=' needs integer values; C has values (LOW, HIGH) "
            "and HIGH is compared; use '==' or '!=' in \"C >= HIGH\" at column 6 (rules here name raw features)"},
        sgtest::SpecErrorCase{
            "valued_name_alone",
            sgtest::replace_once(sgtest::replace_once(kBase, "\"define\": \"HAS_C\"",
                                                      "\"define\": \"HAS_C\", \"values\": [0, 1, 2]"),
                                 "\"A && B\"", "\"C && B\""),
            "spec.json:11:31: error: raw.impossible[0].when: 'C' has values (0, 1, 2); compare it, e.g. C == 0 in "
            "\"C && B\" at column 2 (rules here name raw features)"},
        sgtest::SpecErrorCase{
            "valued_variant_without_value",
            sgtest::replace_once(sgtest::replace_once(kBase, "\"define\": \"HAS_C\"",
                                                      "\"define\": \"HAS_C\", \"values\": [0, 1, 2]"),
                                 "\"A || C\"", "\"A || C == 1\""),
            "spec.json:15:56: error: optimised.variants[0].raw_features[1]: C has values (0, 1, 2); name one, e.g. "
            "\"C=0\""},
        sgtest::SpecErrorCase{
            "impossible_optimised_variant",
            sgtest::replace_once(kBase, "\"raw_features\": [\"A\", \"C\"]", "\"raw_features\": [\"A\", \"B\"]"),
            "(no error)"}),
    [](const ::testing::TestParamInfo<sgtest::SpecErrorCase>& param) { return std::string(param.param.name); });

TEST(SpecErrors, OptimisedPermutationThatIsImpossibleFailsExpansion) {
  auto spec = parse_domain(
      sgtest::replace_once(kBase, "\"raw_features\": [\"A\", \"C\"]", "\"raw_features\": [\"A\", \"B\"]"), "spec.json");
  ASSERT_TRUE(spec.ok());
  // Parsing accepts it; expansion proves every optimised permutation compilable and refuses.
  auto plan = expand(*spec);
  ASSERT_FALSE(plan.ok());
  EXPECT_EQ(plan.errors().front().to_string(),
            "spec.json:11: error: optimised ID 1 (X) is compiled with raw features A | B, which the impossible rule "
            "\"A && B\" prunes");
}

TEST(SpecErrors, MissingFileNamesThePath) {
  auto result = load_domain("/nonexistent/folder/spec.json");
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.errors().front().to_string(), "/nonexistent/folder/spec.json: error: spec file does not exist");
}

TEST(SpecErrors, DirectoryIsNotASpec) {
  auto result = load_domain(sgtest::source_dir());
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.errors().front().message, "spec path is a directory, not a file");
}

TEST(SpecErrors, OversizedSpecIsRejectedBeforeParsing) {
  sgtest::TempDir big_dir("big");
  std::filesystem::path big = big_dir / "big.json";
  sgtest::write_file(big, "\"" + std::string(json::kMaxJsonBytes + 10, 'x') + "\"");
  auto result = load_domain(big);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.errors().front().message, "spec is larger than 1048576 bytes");
}

TEST(SpecErrors, EveryProblemIsReportedNotJustTheFirst) {
  std::string text =
      sgtest::replace_once(sgtest::replace_once(kBase, "\"HAS_C\"", "\"HAS_A\""), "\"format\": 1", "\"formats\": 1");
  auto result = parse_domain(text, "spec.json");
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.errors().size(), 2u);
}

}  // namespace
}  // namespace shadergen
