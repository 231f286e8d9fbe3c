// Compile errors speak in the spec's features: the permutations an error occurs in are named by
// feature (the define in brackets where it differs), with the features they lack where that is
// what sets them apart; glslang's empty-token prefix is gone from its messages.
#include <gtest/gtest.h>

#include <string>

#include "shadergen/build.h"
#include "test_helpers.h"

namespace {

const std::string kSpec = R"({
  "format": 1, "name": "d", "uber_shader": { "path": "s.frag" }, "define_style": "value",
  "raw": { "features": [
    { "name": "LIT", "bit": 0, "define": "HAS_LIGHT" },
    { "name": "SHADING", "bit": 1, "define": "SHADING_MODEL", "values": ["UNLIT", "PBR"] }
  ] }
})";

// The first diagnostic of building `shader` in the domain above.
std::string first_error(const sgtest::TempDir& dir, const std::string& shader) {
  sgtest::write_file(dir / "d.json", kSpec);
  sgtest::write_file(dir / "s.frag", shader);
  auto built = shadergen::build(sgtest::build_options(dir / "d.json", dir / "out", dir / "cache"));
  return built.ok() ? std::string("built") : built.errors().front().to_string();
}

// Reads both features, so that each one's define is read whatever the test adds.
const std::string kHead =
    "#version 450\nlayout(location = 0) out vec4 c;\nvoid main() {\n  c = vec4(HAS_LIGHT ? 1.0 : 0.0, SHADING_MODEL, "
    "0, 1);\n";

TEST(FeatureDiagnostics, AValuedFeatureIsNamedWithItsDefineInBrackets) {
  sgtest::TempDir dir("feature-diagnostics-valued");
  EXPECT_EQ(first_error(dir, kHead + "#if SHADING_MODEL == PBR\n  pbr_only();\n#endif\n}\n"),
            (dir / "s.frag").string() +
                ":6: error: 'pbr_only' : no matching overloaded function found (in 2 of 4 raw permutations: those "
                "with SHADING=PBR [SHADING_MODEL=PBR]; e.g. raw 2 with HAS_LIGHT=0 SHADING_MODEL=PBR)");
}

TEST(FeatureDiagnostics, PermutationsSetApartByWhatTheyLackAreNamedWithout) {
  sgtest::TempDir dir("feature-diagnostics-without");
  EXPECT_EQ(first_error(dir, kHead + "#if !HAS_LIGHT\n  dark_only();\n#endif\n}\n"),
            (dir / "s.frag").string() +
                ":6: error: 'dark_only' : no matching overloaded function found (in 2 of 4 raw permutations: those "
                "without LIT [HAS_LIGHT]; e.g. raw 0 with HAS_LIGHT=0 SHADING_MODEL=UNLIT)");
}

TEST(FeatureDiagnostics, ASyntaxErrorHasNoEmptyTokenPrefix) {
  sgtest::TempDir dir("feature-diagnostics-syntax");
  EXPECT_EQ(first_error(dir, kHead + "  float x = ;\n  x = SHADING_MODEL;\n}\n"),
            (dir / "s.frag").string() +
                ":5: error: syntax error, unexpected SEMICOLON (in 4 of 4 raw permutations: all of them; e.g. raw 0 "
                "with HAS_LIGHT=0 SHADING_MODEL=UNLIT)");
}

}  // namespace
