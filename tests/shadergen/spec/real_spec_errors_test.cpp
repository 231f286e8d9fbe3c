// Diagnostics for a broken copy of the real domain spec (permutations/split_second.json), the
// file an engineer actually edits: each case makes one edit to the text in memory, parses it
// with parse_domain() under the name "split_second.json", and asserts the whole diagnostic
// string, "file:line:column: error: key.path: problem". Line and column are computed from
// the edited text (the position of the offending value), so the expectations stay exact
// without depending on the spec's current layout; each case also checks its anchor exists.
#include <gtest/gtest.h>

#include "shadergen/domain.h"
#include "shadergen/expression.h"
#include "shadergen/permutations.h"
#include "spec/json.h"
#include "test_helpers.h"

namespace {

const std::string kFile = "split_second.json";

const std::string& real_spec() {
  static const std::string text = sgtest::read_file(sgtest::split_second_spec());
  return text;
}

// The first diagnostic of parsing `text`, or "(no error)".
std::string first_error(const std::string& text) {
  auto result = shadergen::parse_domain(text, kFile);
  if (result.ok()) return "(no error)";
  return result.errors().front().to_string();
}

// The spec with the first occurrence of `from` (after `after`, when given) replaced by `to`.
struct Edit {
  std::string text;
  std::size_t at = std::string::npos;  // where the replacement starts
};
Edit edit(const std::string& from, const std::string& to, const std::string& after = {}) {
  Edit e{real_spec()};
  std::size_t start = after.empty() ? 0 : e.text.find(after);
  if (start == std::string::npos) return e;
  e.at = e.text.find(from, start);
  if (e.at != std::string::npos) e.text.replace(e.at, from.size(), to);
  return e;
}

std::string located(const Edit& e, std::size_t offset_in_replacement, const std::string& message) {
  return sgtest::where(kFile, e.text, e.at + offset_in_replacement) + ": error: " + message;
}

const char* kRawNames = "SHADOW_SOLID, SHADOW_SOFT, SHADOW_FADE, LIGHT_SCATTERING, MSAA_EDGE, SKY, SUN_LIGHT";

TEST(RealSpec, ParsesAndExpandsWithoutError) {
  EXPECT_EQ(first_error(real_spec()), "(no error)");
  auto spec = shadergen::parse_domain(real_spec(), kFile);
  ASSERT_TRUE(spec.ok());
  EXPECT_EQ(spec->raw_space(), 128u);
  EXPECT_EQ(spec->optimised_count(), 32u);
  EXPECT_TRUE(shadergen::expand(*spec).ok());
}

// --- truncated files --------------------------------------------------------------------

std::string truncated_at_end(const std::string& cut, const std::string& message) {
  return sgtest::where(kFile, cut, cut.size()) + ": error: " + message;
}

TEST(RealSpecTruncated, CutInHalf) {
  const std::string half = real_spec().substr(0, real_spec().size() / 2);
  const std::string error = first_error(half);
  // Where half of the file ends decides the message; every one says where the file ends.
  const bool inside_string = sgtest::count_of(half.substr(half.rfind('\n') + 1), "\"") % 2 == 1;
  if (inside_string) {
    EXPECT_EQ(error, truncated_at_end(half, "unterminated string"));
  } else {
    EXPECT_TRUE(sgtest::contains(error, "(the spec is truncated?)")) << error;
    EXPECT_EQ(error.rfind(sgtest::where(kFile, half, half.size()) + ": error: ", 0), 0u) << error;
  }
}

TEST(RealSpecTruncated, EveryCutIsAnErrorAtTheEndOfTheText) {
  // Cutting anywhere at all must fail, and the diagnostic must point at (or before) the end.
  const std::string& text = real_spec();
  std::size_t last = text.find_last_not_of(" \n");
  for (std::size_t size = 0; size <= last; size += 7) {
    const std::string cut = text.substr(0, size);
    auto result = shadergen::parse_domain(cut, kFile);
    ASSERT_FALSE(result.ok()) << "a spec cut to " << size << " bytes parsed";
    const shadergen::Diagnostic& d = result.errors().front();
    sgtest::Position end = sgtest::position_of(cut, cut.size());
    EXPECT_TRUE(d.line < end.line || (d.line == end.line && d.column <= end.column))
        << "cut to " << size << ": " << d.to_string();
  }
}

struct CutCase {
  const char* name;
  std::string after;  // the text is cut just after the first occurrence of this
  std::string message;
};

// Test names and failure messages show the case's name, not the bytes of the struct.
void PrintTo(const CutCase& c, std::ostream* os) { *os << c.name; }

class RealSpecCut : public ::testing::TestWithParam<CutCase> {};

TEST_P(RealSpecCut, ExactDiagnostic) {
  const std::string& text = real_spec();
  std::size_t at = text.find(GetParam().after);
  ASSERT_NE(at, std::string::npos) << "test bug: anchor not in the spec";
  const std::string cut = text.substr(0, at + GetParam().after.size());
  EXPECT_EQ(first_error(cut), truncated_at_end(cut, GetParam().message));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, RealSpecCut,
    ::testing::Values(CutCase{"inside_object", "\"optimised\": {",
                              "unexpected end of file inside an object (the spec is truncated?)"},
                      CutCase{"after_member", "\"format\": 1,",
                              "unexpected end of file inside an object (the spec is truncated?)"},
                      CutCase{"inside_array", "\"include_dirs\": [\"../uber/include\"",
                              "unexpected end of file inside an array (the spec is truncated?)"},
                      // Right after an opening bracket the reader expects a value (and says only that).
                      CutCase{"array_start", "\"features\": [", "unexpected end of file (the spec is truncated?)"},
                      CutCase{"before_value", "\"format\":", "unexpected end of file (the spec is truncated?)"},
                      CutCase{"inside_string", "\"name\": \"split_", "unterminated string"}),
    [](const ::testing::TestParamInfo<CutCase>& param) { return std::string(param.param.name); });

TEST(RealSpecTruncated, EmptyFile) {
  EXPECT_EQ(first_error(""), "split_second.json:1:1: error: unexpected end of file (the spec is truncated?)");
  EXPECT_EQ(first_error("  \n  "), "split_second.json:2:3: error: unexpected end of file (the spec is truncated?)");
}

// --- one semantic mistake each ------------------------------------------------------------

struct EditCase {
  const char* name;
  std::string from;
  std::string to;
  std::string after;    // search for `from` only after this anchor ("" = from the start)
  std::size_t offset;   // where, inside `to`, the diagnostic points
  std::string message;  // without the "file:line:column: error: " prefix
};

void PrintTo(const EditCase& c, std::ostream* os) { *os << c.name; }

class RealSpecEdit : public ::testing::TestWithParam<EditCase> {};

TEST_P(RealSpecEdit, ExactDiagnostic) {
  const EditCase& c = GetParam();
  Edit e = edit(c.from, c.to, c.after);
  ASSERT_NE(e.at, std::string::npos) << "test bug: '" << c.from << "' not in the spec";
  EXPECT_EQ(first_error(e.text), located(e, c.offset, c.message));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, RealSpecEdit,
    ::testing::Values(
        EditCase{"bit_collision", "\"bit\": 5", "\"bit\": 3", "\"SKY\"", 7,
                 "raw.features[5].bit: bit 3 of SKY collides with feature LIGHT_SCATTERING"},
        EditCase{"optimised_bit_collision", "\"bit\": 4", "\"bit\": 3", "\"SUN_1\"", 7,
                 "optimised.bits[4].bit: bit 3 of SUN_1 collides with optimised bit SUN_0"},
        EditCase{"duplicate_define", "\"define\": \"SKY\"", "\"define\": \"MSAA_EDGE\"", "\"SKY\"", 10,
                 "raw.features[5].define: define MSAA_EDGE is already used by feature MSAA_EDGE"},
        EditCase{"duplicate_feature_name", "\"name\": \"SUN_LIGHT\"", "\"name\": \"SKY\"", "", 8,
                 "raw.features[6].name: feature \"SKY\" is declared twice"},
        EditCase{"unknown_name_in_impossible_rule", "\"SHADOW_SOLID && SHADOW_SOFT\"",
                 "\"SHADOW_SOLID && SHADOW_SOFTER\"", "", 0,
                 std::string("raw.impossible[0].when: unknown name 'SHADOW_SOFTER' (known: ") + kRawNames +
                     ") in \"SHADOW_SOLID && SHADOW_SOFTER\" at column 17 (rules here name raw features)"},
        EditCase{"unknown_name_in_optimised_bit", "\"!SHADOW_SOLID && SUN_LIGHT\"", "\"!SHADOW_SOLID && SUN\"", "", 0,
                 std::string("optimised.bits[4].when: unknown name 'SUN' (known: ") + kRawNames +
                     ") in \"!SHADOW_SOLID && SUN\" at column 18 (rules here name raw features)"},
        EditCase{"raw_name_in_variant_rule", "\"!SUN_1 && !SUN_0\"", "\"!SUN_1 && !SHADOW_SOLID\"", "", 0,
                 "optimised.variants[3].when: unknown name 'SHADOW_SOLID' (known: LIGHT_SCATTERING, MSAA_EDGE, SKY, "
                 "SUN_0, SUN_1) in \"!SUN_1 && !SHADOW_SOLID\" at column 12 (rules here name optimised bits)"},
        EditCase{"unknown_raw_feature_in_variant", "[\"SUN_LIGHT\"]", "[\"SUN\"]", "\"variants\"", 1,
                 std::string("optimised.variants[5].raw_features[0]: unknown raw feature \"SUN\" (known: ") +
                     kRawNames + ")"},
        EditCase{"rule_syntax_error", "\"!SHADOW_SOLID && SUN_LIGHT\"", "\"!SHADOW_SOLID && && SUN_LIGHT\"", "", 0,
                 "optimised.bits[4].when: expected a feature name, '!' or '(' but found '&' in \"!SHADOW_SOLID && && "
                 "SUN_LIGHT\" at column 18 (rules here name raw features)"},
        EditCase{"rule_single_ampersand", "\"SHADOW_SOLID && SHADOW_SOFT\"", "\"SHADOW_SOLID & SHADOW_SOFT\"", "", 0,
                 "raw.impossible[0].when: '&' is not an operator; use '&&' or '||' in \"SHADOW_SOLID & SHADOW_SOFT\" "
                 "at column 14 (rules here name raw features)"},
        EditCase{"rule_unbalanced_parenthesis", "\"(SHADOW_SOLID && SHADOW_FADE && SUN_LIGHT)",
                 "\"((SHADOW_SOLID && SHADOW_FADE && SUN_LIGHT)", "", 0,
                 "optimised.bits[3].when: missing ')' in \"((SHADOW_SOLID && SHADOW_FADE && SUN_LIGHT) || "
                 "(!SHADOW_SOLID && SUN_LIGHT && SHADOW_SOFT)\" at column 91 (rules here name raw features)"},
        EditCase{"unknown_key_in_feature", "\"description\": \"a pixel is sky\"", "\"descripton\": \"a pixel is sky\"",
                 "", 14,
                 "raw.features[5]: unknown key \"descripton\" (expected one of: name, bit, define, values, "
                 "description, kind, constant_id, define_style, "
                 "unread)"},
        EditCase{"unknown_top_level_key", "\"include_dirs\"", "\"include_dir\"", "", 15,
                 "spec: unknown key \"include_dir\" (expected one of: format, name, description, uber_shader, "
                 "uber_shaders, program, include_dirs, target_env, layout, strip_debug, defines, companions, raw, "
                 "optimised, compile, variants_file, define_style, branch_block)"},
        EditCase{"bit_out_of_range", "\"bit\": 6", "\"bit\": 7", "\"SUN_LIGHT\"", 7,
                 "raw.features[6].bit: bit must be an integer from 0 to 6, found 7"},
        EditCase{"negative_bit", "\"bit\": 0", "\"bit\": -1", "", 7,
                 "raw.features[0].bit: bit must be an integer from 0 to 6, found -1"},
        EditCase{"fractional_bit", "\"bit\": 2", "\"bit\": 2.5", "", 7,
                 "raw.features[2].bit: bit must be an integer from 0 to 6, found 2.5"},
        EditCase{"optimised_bit_out_of_range", "\"bit\": 4", "\"bit\": 5", "\"SUN_1\"", 7,
                 "optimised.bits[4].bit: bit must be an integer from 0 to 4, found 5"},
        EditCase{"bit_is_a_string", "\"bit\": 0", "\"bit\": \"0\"", "", 7,
                 "raw.features[0].bit: expected a number, found a string"},
        EditCase{"include_dirs_is_a_string", "[\"../uber/include\"]", "\"../uber/include\"", "", 0,
                 "spec.include_dirs: expected an array, found a string"},
        EditCase{"define_not_an_identifier", "\"define\": \"SKY\"", "\"define\": \"SKY-BOX\"", "", 10,
                 "raw.features[5].define: \"SKY-BOX\" is not a GLSL identifier"},
        EditCase{"unknown_stage", "\"stage\": \"fragment\"", "\"stage\": \"pixel\"", "", 9,
                 "uber_shaders.raster.stage: unknown stage \"pixel\" (expected one of vertex, tess_control, "
                 "tess_evaluation, "
                 "geometry, fragment, compute, task, mesh, ray_generation, any_hit, closest_hit, miss, intersection, "
                 "callable, or .vert .tesc .tese .geom .frag .comp .task .mesh .rgen .rahit .rchit .rmiss .rint .rcall "
                 "without the dot)"},
        EditCase{"unsupported_format", "\"format\": 1", "\"format\": 2", "", 10,
                 "spec.format: unsupported format version (this shadergen reads 1)"},
        EditCase{"duplicate_key", "\"name\": \"split_second\",", "\"name\": \"split_second\", \"name\": \"x\",", "", 24,
                 "duplicate key \"name\""},
        EditCase{"trailing_comma",
                 "\"SUN_1 && SUN_0\",   \"raw_features\": [\"SHADOW_SOFT\", \"SHADOW_FADE\", \"SUN_LIGHT\"]",
                 "\"SUN_1 && SUN_0\",   \"raw_features\": [\"SHADOW_SOFT\", \"SHADOW_FADE\", \"SUN_LIGHT\",]", "", 78,
                 "trailing comma before ']' (JSON allows none: remove it)"},
        EditCase{"trailing_comma_in_an_object", "\"name\": \"split_second\",", "\"name\": \"split_second\", }", "", 22,
                 "trailing comma before '}' (JSON allows none: remove it)"}),
    [](const ::testing::TestParamInfo<EditCase>& param) { return std::string(param.param.name); });

TEST(RealSpec, NestingBeyondTheDepthLimitIsRefused) {
  // include_dirs becomes 40 nested arrays: the 32nd opening bracket is one level too deep
  // (the spec's own object is the first level).
  const std::string deep = std::string(40, '[') + "\"x\"" + std::string(40, ']');
  Edit e = edit("[\"../uber/include\"]", deep);
  ASSERT_NE(e.at, std::string::npos);
  EXPECT_EQ(first_error(e.text),
            located(e, shadergen::json::kMaxJsonDepth - 1,
                    "nesting deeper than " + std::to_string(shadergen::json::kMaxJsonDepth) + " levels"));
  // One level less is valid JSON (then rejected by the schema, not by the reader).
  const std::string ok_depth = std::string(30, '[') + "\"x\"" + std::string(30, ']');
  Edit shallow = edit("[\"../uber/include\"]", ok_depth);
  EXPECT_EQ(first_error(shallow.text), located(shallow, 1, "include_dirs[0]: expected a string"));
}

TEST(RealSpec, RuleNestingLimit) {
  // The outermost operand is level 1, so 63 nested parentheses make 64 levels: the limit.
  const std::string rule = "\"!SHADOW_SOLID && SUN_LIGHT\"";
  const int max_parens = shadergen::kMaxExpressionDepth - 1;
  const std::string at_limit = std::string(static_cast<std::size_t>(max_parens), '(') + "SUN_LIGHT" +
                               std::string(static_cast<std::size_t>(max_parens), ')');
  Edit ok = edit(rule, "\"" + at_limit + "\"");
  ASSERT_NE(ok.at, std::string::npos);
  EXPECT_EQ(first_error(ok.text), "(no error)");

  const std::string too_deep = "(" + at_limit + ")";
  Edit deep = edit(rule, "\"" + too_deep + "\"");
  EXPECT_EQ(first_error(deep.text),
            located(deep, 0,
                    "optimised.bits[4].when: expression nested deeper than 64 levels in \"" + too_deep +
                        "\" at column " + std::to_string(max_parens + 2) + " (rules here name raw features)"));
  // Negations count as levels too.
  Edit negations = edit(rule, "\"" + std::string(static_cast<std::size_t>(max_parens + 1), '!') + "SUN_LIGHT\"");
  EXPECT_TRUE(sgtest::contains(first_error(negations.text), "expression nested deeper than 64 levels"))
      << first_error(negations.text);
}

TEST(RealSpec, HostileNestingDoesNotExhaustTheStack) {
  const std::string bomb = std::string(200000, '[');
  // The 33rd bracket is the first one too deep.
  EXPECT_EQ(first_error(bomb), "split_second.json:1:33: error: nesting deeper than 32 levels");
  const std::string limit = std::string(32, '[') + std::string(32, ']');
  EXPECT_EQ(first_error(limit), "split_second.json:1:1: error: spec: the spec must be a JSON object")
      << "32 levels are allowed";
}

TEST(RealSpec, MissingFileNamesThePath) {
  sgtest::TempDir dir("missing-spec");
  const sgtest::fs::path missing = dir / "permutations" / "split_second.json";
  auto result = shadergen::load_domain(missing);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.errors().front().to_string(), missing.string() + ": error: spec file does not exist");
}

TEST(RealSpec, LoadDomainReportsTheRealPath) {
  sgtest::TempDir dir("broken-spec");
  Edit e = edit("\"bit\": 5", "\"bit\": 3", "\"SKY\"");
  ASSERT_NE(e.at, std::string::npos);
  const sgtest::fs::path file = dir / "split_second.json";
  sgtest::write_file(file, e.text);
  auto result = shadergen::load_domain(file);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.errors().front().to_string(),
            sgtest::where(file.string(), e.text, e.at + 7) +
                ": error: raw.features[5].bit: bit 3 of SKY collides with feature LIGHT_SCATTERING");
}

TEST(RealSpec, SeveralMistakesAreAllReported) {
  Edit e = edit("\"bit\": 5", "\"bit\": 3", "\"SKY\"");
  const std::string twice = e.text;
  auto at = twice.find("\"define\": \"SUN_LIGHT\"");
  ASSERT_NE(at, std::string::npos);
  std::string text = twice;
  text.replace(at, 21, "\"define\": \"SKY\"");
  auto result = shadergen::parse_domain(text, kFile);
  ASSERT_FALSE(result.ok());
  ASSERT_EQ(result.errors().size(), 2u);
  EXPECT_TRUE(sgtest::contains(result.errors()[0].message, "bit 3 of SKY collides with feature LIGHT_SCATTERING"));
  EXPECT_EQ(result.errors()[1].message, "raw.features[6].define: define SKY is already used by feature SKY");
}

}  // namespace
