// Bad input to the new spec keys, through the shadergen executable: each broken copy of the
// valued-features fixture is refused with one exact message naming the spec (file, line and
// column of the offending value), the key and the value; the exit status is 1; and the
// output folder built before from the good spec is left byte for byte as it was.
#include <gtest/gtest.h>

#include "test_helpers.h"

namespace {

struct BadInput {
  const char* name;
  std::string from, to;  // the edit to valued.json
  std::string at;        // the text whose first character the message points at (after the edit)
  std::string message;   // after "<file>:<line>:<column>: error: "
};

void PrintTo(const BadInput& c, std::ostream* os) { *os << c.name; }

class BadSpecInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(BadSpecInput, ExactMessageExitOneAndTheOutputIntact) {
  const BadInput& c = GetParam();
  sgtest::TempDir dir("bad-input");
  for (const auto& [name, bytes] : sgtest::snapshot(sgtest::fixtures_dir() / "valued"))
    sgtest::write_file(dir / ("spec/" + name), bytes);
  const sgtest::fs::path spec = dir / "spec" / "valued.json";
  const std::vector<std::string> args = {"build",       spec.string(),           "--out", (dir / "out").string(),
                                         "--cache-dir", (dir / "cache").string()};
  sgtest::ProcessResult good = sgtest::run_process(sgtest::shadergen_exe(), args);
  ASSERT_EQ(good.exit_code, 0) << good.err;
  auto before = sgtest::snapshot(dir / "out");

  std::string text = sgtest::read_file(spec);
  std::size_t edit = text.find(c.from);
  ASSERT_NE(edit, std::string::npos) << "test bug: " << c.from;
  text.replace(edit, c.from.size(), c.to);
  sgtest::write_file(spec, text);
  std::size_t at = text.find(c.at);
  ASSERT_NE(at, std::string::npos) << "test bug: " << c.at;

  sgtest::ProcessResult bad = sgtest::run_process(sgtest::shadergen_exe(), args);
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_EQ(bad.err, sgtest::where(spec.string(), text, at) + ": error: " + c.message + "\n");
  EXPECT_EQ(sgtest::snapshot(dir / "out"), before);
}

INSTANTIATE_TEST_SUITE_P(
    Cases, BadSpecInput,
    ::testing::Values(
        BadInput{"duplicate_value", "\"values\": [0, 1, 2]", "\"values\": [0, 1, 1]", "1] }",
                 "raw.features[1].values[2]: value 1 is listed twice"},
        BadInput{"value_neither_integer_nor_identifier", "\"values\": [0, 1, 2]", "\"values\": [0, 1.5, 2]", "1.5",
                 "raw.features[1].values[1]: expected an integer or an identifier, found 1.5"},
        BadInput{"identifier_value_with_a_dash", "\"FILMIC\"]", "\"FILM-IC\"]", "\"FILM-IC\"",
                 "raw.features[2].values[2]: expected an integer or an identifier, found \"FILM-IC\""},
        BadInput{"boolean_compared_with_a_number", "\"TAA_QUALITY == 0 && SHARPEN\"",
                 "\"TAA_QUALITY == 0 && SHARPEN == 1\"", "\"TAA_QUALITY == 0 && SHARPEN == 1\"",
                 "raw.impossible[0].when: 'SHARPEN' is a boolean feature; it cannot be compared with a number (write "
                 "SHARPEN or !SHARPEN) in \"TAA_QUALITY == 0 && SHARPEN == 1\" at column 21 (rules here name raw "
                 "features)"},
        BadInput{"equality_on_an_unknown_value", "\"TONEMAP != LINEAR\"", "\"TONEMAP == SEPIA\"",
                 "\"TONEMAP == SEPIA\"",
                 "optimised.bits[1].when: 'TONEMAP' has no value SEPIA (values: LINEAR, ACES, FILMIC) in \"TONEMAP == "
                 "SEPIA\" at column 12 (rules here name raw features)"},
        BadInput{"unknown_target_env", "\"format\": 1,", "\"format\": 1, \"target_env\": \"vulkan2.0\",",
                 "\"vulkan2.0\"",
                 "target_env: unknown target environment \"vulkan2.0\" (expected vulkan1.0, vulkan1.1, vulkan1.2 or "
                 "vulkan1.3)"},
        BadInput{"unknown_stage", "\"stage\": \"fragment\"", "\"stage\": \"pixel\"", "\"pixel\"",
                 "uber_shader.stage: unknown stage \"pixel\" (expected one of vertex, tess_control, tess_evaluation, "
                 "geometry, fragment, compute, task, mesh, ray_generation, any_hit, closest_hit, miss, intersection, "
                 "callable, or .vert .tesc .tese .geom .frag .comp .task .mesh .rgen .rahit .rchit .rmiss .rint .rcall "
                 "without the dot)"},
        BadInput{"extension_that_names_no_stage", "{ \"path\": \"taa_resolve.frag\", \"stage\": \"fragment\" }",
                 "{ \"path\": \"taa_resolve.glsl\" }", "{ \"path\": \"taa_resolve.glsl\" }",
                 "uber_shader: missing \"stage\", and the extension of \"taa_resolve.glsl\" names none (one of .vert "
                 ".tesc .tese .geom .frag .comp .task .mesh .rgen .rahit .rchit .rmiss .rint .rcall does)"}),
    [](const ::testing::TestParamInfo<BadInput>& p) { return std::string(p.param.name); });

}  // namespace
