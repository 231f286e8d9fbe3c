// The "program" form (tests/fixtures/program): a vertex and a fragment shader permuted
// together, each permutation compiling both with the same defines; the manifest and the
// registry give both halves, and a permutation whose fragment half reads a varying that its
// vertex half does not write (or writes narrower) is refused, by name, once for all the
// permutations that have the problem; errors count raw permutations and name the half.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "shadergen/build.h"
#include "test_helpers.h"

namespace {

using nlohmann::json;
using sgtest::fs::path;

// A copy of the fixture with `from` replaced by `to` in `file`.
path broken_copy(const sgtest::TempDir& dir, const std::string& file, const std::string& from, const std::string& to) {
  for (const auto& [name, bytes] : sgtest::snapshot(sgtest::fixtures_dir() / "program"))
    sgtest::write_file(dir / ("spec/" + name), bytes);
  std::string text = sgtest::read_file(dir / ("spec/" + file));
  text.replace(text.find(from), from.size(), to);
  sgtest::write_file(dir / ("spec/" + file), text);
  return dir / "spec" / "program.json";
}

TEST(ProgramForm, EveryPermutationHasBothHalvesWithTheSameDefines) {
  sgtest::TempDir dir("program");
  auto summary = sgtest::build(sgtest::fixtures_dir() / "program" / "program.json", dir / "out", dir / "cache");
  ASSERT_TRUE(summary.ok()) << summary.errors().front().to_string();
  EXPECT_EQ(summary->permutations, 8u) << "4 raw IDs, two shaders each";
  EXPECT_EQ(summary->unique_sources, 8u);
  json manifest = json::parse(sgtest::read_file(dir / "out" / "manifest.json"));
  EXPECT_EQ(manifest["uber_shader"], "surface.frag");
  EXPECT_EQ(manifest["vertex_shader"], "surface.vert");
  for (const json& raw : manifest["raw"]) {
    ASSERT_TRUE(raw.contains("vertex_spirv")) << raw.dump();
    std::string vertex = raw["vertex_spirv"], fragment = raw["spirv"];
    EXPECT_NE(vertex, fragment);
    for (const json& blob : manifest["blobs"]) {
      if (blob["spirv"] == vertex) {
        EXPECT_EQ(blob["stage"], "vertex");
      }
      if (blob["spirv"] == fragment) {
        EXPECT_EQ(blob["stage"], "fragment");
      }
    }
    sgtest::ProcessResult val = sgtest::spirv_val(dir / "out" / vertex);
    EXPECT_EQ(val.exit_code, 0) << val.err;
  }
  std::string source = sgtest::read_file(dir / "out" / "surface_program.cpp");
  EXPECT_EQ(sgtest::count_of(source, "&kReflections["), 4u) << "each raw permutation points at its vertex half";
}

TEST(ProgramForm, AFragmentInputTheVertexHalfDoesNotWriteIsRefused) {
  sgtest::TempDir dir("program-missing");
  path spec = broken_copy(dir, "surface.vert", "layout(location = 2) out float out_fog;",
                          "layout(location = 3) out float out_fog;");
  auto result = sgtest::build(spec, dir / "out", dir / "cache");
  ASSERT_FALSE(result.ok());
  ASSERT_EQ(result.errors().size(), 1u) << "raw 2 and raw 3 have one problem, said once";
  // Said at the input's declaration in the fragment shader.
  EXPECT_EQ(result.errors()[0].to_string(),
            (spec.parent_path() / "surface.frag").string() +
                ":8: error: the fragment shader reads location 2 (\"in_fog\", 1 components), which the vertex shader "
                "does not write (in 2 of 4 raw permutations (fragment shader): those with FOG; e.g. raw 2 with FOG)");
  EXPECT_FALSE(sgtest::fs::exists(dir / "out"));
}

TEST(ProgramForm, ANarrowerVertexOutputIsRefused) {
  sgtest::TempDir dir("program-narrow");
  path spec = broken_copy(dir, "surface.frag", "layout(location = 0) in vec3 in_normal;",
                          "layout(location = 0) in vec4 in_normal4;\n#define in_normal in_normal4.xyz");
  auto result = sgtest::build(spec, dir / "out", dir / "cache");
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.errors()[0].to_string(),
            (spec.parent_path() / "surface.frag").string() +
                ":3: error: the fragment shader reads location 0 (\"in_normal4\", 4 components), which the vertex "
                "shader writes with 3 (\"out_normal\") (in 4 of 4 raw permutations (fragment shader): all of them; "
                "e.g. raw 0 (no defines))");
}

// A GLSL error in one half: counted by raw permutation, not by shader, and the half is named.
TEST(ProgramForm, ErrorsCountRawPermutationsAndNameTheHalf) {
  sgtest::TempDir dir("program-vertex-error");
  path spec = broken_copy(dir, "surface.vert", "out_fog = clamp(", "out_fog = undeclared_fog + clamp(");
  auto result = sgtest::build(spec, dir / "out", dir / "cache");
  ASSERT_FALSE(result.ok());
  std::string errors = result.errors().front().to_string();
  EXPECT_TRUE(sgtest::contains(errors,
                               "'undeclared_fog' : undeclared identifier (in 2 of 4 raw permutations (vertex "
                               "shader): those with FOG; e.g. raw 2 vertex with FOG)"))
      << errors;
}

TEST(ProgramForm, UberShaderAndProgramTogetherIsAnError) {
  sgtest::TempDir dir("program-both");
  path spec = broken_copy(dir, "program.json",
                          "\"program\":", "\"uber_shader\": { \"path\": \"surface.frag\" },\n  \"program\":");
  auto result = sgtest::build(spec, dir / "out", dir / "cache");
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.errors()[0].to_string(),
            spec.string() + ":6:14: error: program: a spec has \"uber_shader\" or \"program\", not both");
}

}  // namespace
