// GLSL diagnostics across permutations (tests/fixtures/follow_on): glslang's follow-on
// messages at the line of a permutation's first error are folded into it, the first error of
// each permutation is printed first, and a message counts every permutation that reaches its
// line (here an error in an include that the FANCY permutations never got to, because
// glslang stopped at their first error).
#include <gtest/gtest.h>

#include "compile/error_grouping.h"
#include "shadergen/build.h"
#include "test_helpers.h"

namespace {

TEST(FollowOnErrors, FirstErrorsFirstNoiseFoldedEveryPermutationCounted) {
  sgtest::TempDir dir("follow-on");
  shadergen::BuildOptions options =
      sgtest::build_options(sgtest::fixtures_dir() / "follow_on" / "follow_on.json", dir / "out", {});
  options.use_cache = false;
  auto result = shadergen::build(options);
  ASSERT_FALSE(result.ok());
  const std::string folder = (sgtest::fixtures_dir() / "follow_on").lexically_normal().string();
  std::vector<std::string> printed;
  for (const shadergen::Diagnostic& d : result.errors()) printed.push_back(d.to_string());
  EXPECT_EQ(printed, (std::vector<std::string>{
                         folder + "/cascade.frag:9: error: 'undefined_fn' : no matching overloaded function found "
                                  "(in 2 of 4 raw permutations: those with FANCY; e.g. raw 1 with FANCY)",
                         folder + "/include/cascade_common.glsl:3: error: 'missing_alpha' : undeclared identifier "
                                  "(in 4 of 4 raw permutations: all of them; e.g. raw 0 (no defines))",
                     }));
  EXPECT_FALSE(sgtest::fs::exists(dir / "out"));
}

TEST(FollowOnErrors, LiveLinesFollowIncludeMarkersAndSkipThePreamble) {
  const std::string text =
      "#extension GL_GOOGLE_include_directive : require\n#version 450\n\nvoid main(){\n#line 1 \"inc.glsl\"\n"
      "float f(){\n#line 5 \"main.frag\"\n}\n";
  shadergen::LiveLines lines = shadergen::live_lines(text, "main.frag");
  EXPECT_EQ(lines, (shadergen::LiveLines{{{"main.frag", 1}, "#version 450"},
                                         {{"main.frag", 3}, "void main(){"},
                                         {{"inc.glsl", 1}, "float f(){"},
                                         {{"main.frag", 5}, "}"}}));
}

}  // namespace
