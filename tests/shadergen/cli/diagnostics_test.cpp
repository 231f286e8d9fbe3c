// Diagnostics a user can act on, each asserted exactly: a missing shader file at the spec key
// and line that names it (a companion by its name), optimised IDs that no raw ID reaches, and -v listing every permutation of an error whose permutations
// share no define set. Every spec is written into a temporary folder by the test itself.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "shadergen/build.h"
#include "test_helpers.h"

namespace {

std::string all_errors(const shadergen::Result<shadergen::BuildSummary>& result) {
  std::string text;
  if (!result.ok())
    for (const shadergen::Diagnostic& d : result.errors()) text += d.to_string() + "\n";
  return text;
}

TEST(Diagnostics, AMissingShaderFileIsNamedAtItsSpecKey) {
  sgtest::TempDir dir("missing-shader");
  const std::string spec_text = R"({
  "format": 1,
  "name": "missing",
  "program": { "vertex": "surface.vert",
               "fragment": "missing.frag" },
  "companions": [ { "name": "sort", "path": "nope.comp" } ],
  "raw": { "features": [ { "name": "A", "bit": 0, "define": "A" } ] }
}
)";
  sgtest::write_file(dir / "spec.json", spec_text);
  sgtest::write_file(dir / "surface.vert", sgtest::read_file(sgtest::fixtures_dir() / "program" / "surface.vert"));
  const std::string spec = (dir / "spec.json").string();
  auto result = sgtest::build(dir / "spec.json", dir / "out", dir / "cache");
  EXPECT_EQ(all_errors(result),
            sgtest::where(spec, spec_text, spec_text.find("\"missing.frag\"")) +
                ": error: program.fragment: shader file " + (dir / "missing.frag").string() + " does not exist\n" +
                sgtest::where(spec, spec_text, spec_text.find("\"nope.comp\"")) +
                ": error: companion \"sort\": " + "shader file " + (dir / "nope.comp").string() + " does not exist\n");
}

TEST(Diagnostics, OptimisedIdsNoRawIdReachesAreNamed) {
  sgtest::TempDir dir("unreachable");
  for (const auto& [name, bytes] : sgtest::snapshot(sgtest::fixtures_dir() / "toy"))
    sgtest::write_file(dir / ("toy/" + name), bytes);
  std::string spec_text = sgtest::read_file(dir / "toy" / "toy.json");
  // DISTORT && LIT is impossible, so no raw ID sets SAMPLED: optimised IDs 2 and 3 are unreachable.
  const std::string from = "\"when\": \"TEXTURED || SOFT\"";
  spec_text.replace(spec_text.find(from), from.size(), "\"when\": \"DISTORT && LIT\"");
  sgtest::write_file(dir / "toy" / "toy.json", spec_text);
  shadergen::BuildOptions options = sgtest::build_options(dir / "toy" / "toy.json", dir / "out", dir / "cache");
  std::vector<std::string> lines;
  options.log = [&](const std::string& line) { lines.push_back(line); };
  auto result = shadergen::build(options);
  ASSERT_TRUE(result.ok()) << all_errors(result);
  EXPECT_EQ(lines.front(), "warning: " + (dir / "toy" / "toy.json").string() +
                               ": optimised IDs 2, 3 are reached by no raw ID; compiled all the same (`shadergen lut` "
                               "shows the table; to avoid them, change the optimised bits' \"when\" rules so that no "
                               "combination of bits is impossible, or use fewer bits)");
}

TEST(Diagnostics, VerboseListsEveryPermutationOfAnErrorWithNoSharedDefines) {
  sgtest::TempDir dir("no-shared-defines");
  sgtest::write_file(dir / "spec.json", R"({
  "format": 1,
  "name": "either",
  "uber_shader": { "path": "either.frag" },
  "raw": { "features": [ { "name": "A", "bit": 0, "define": "A" }, { "name": "B", "bit": 1, "define": "B" } ] }
}
)");
  sgtest::write_file(dir / "either.frag",
                     "#version 450\nlayout(location = 0) out vec4 colour;\nvoid main() {\n"
                     "#if (defined(A) && !defined(B)) || (defined(B) && !defined(A))\n  colour = missing;\n#else\n"
                     "  colour = vec4(1);\n#endif\n}\n");
  const std::string file = (dir / "either.frag").lexically_normal().string();
  auto quiet = sgtest::build(dir / "spec.json", dir / "out", dir / "cache");
  EXPECT_EQ(all_errors(quiet),
            file + ":5: error: 'missing' : undeclared identifier (in 2 of 4 raw permutations; e.g. raw 1 with A)\n");
  shadergen::BuildOptions options = sgtest::build_options(dir / "spec.json", dir / "out", dir / "cache");
  options.verbose = true;
  EXPECT_EQ(all_errors(shadergen::build(options)),
            file +
                ":5: error: 'missing' : undeclared identifier (in 2 of 4 raw permutations; namely raw 1 with A, "
                "raw 2 with B)\n");
}

}  // namespace
