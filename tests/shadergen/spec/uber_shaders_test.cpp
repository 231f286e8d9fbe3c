// "uber_shaders": one domain compiled from several uber-shaders. The spec checks (exact
// messages), the per-entry specs the build compiles, and a build of the fixture
// tests/fixtures/several_ubers: one table, one manifest listing each entry's blobs.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "shadergen/build.h"
#include "shadergen/domain.h"
#include "spec/uber_shader_entries.h"
#include "test_helpers.h"

namespace shadergen {
// A namespace of this file's own: the test executables are unity builds (tests/CMakeLists.txt).
namespace uber_shaders_test {
namespace {

// Line numbers in the expectations below refer to this text.
const std::string kBase = R"({
  "format": 1,
  "name": "two",
  "uber_shaders": {
    "raster": { "path": "two.frag", "stage": "fragment" },
    "compute": { "path": "two.comp" }
  },
  "companions": [
    { "name": "quad", "path": "quad.vert" },
    { "name": "prepass", "uber_shader": "compute", "path": "prepass.comp" }
  ],
  "raw": {
    "features": [
      { "name": "A", "bit": 0, "define": "HAS_A" },
      { "name": "B", "bit": 1, "define": "HAS_B" }
    ]
  },
  "optimised": { "ignore": [ { "feature": "B", "when": "A" } ] }
}
)";

TEST(UberShaders, EachEntryCompilesTheDomainWithItsOwnCompanions) {
  auto spec = parse_domain(kBase, "spec.json");
  ASSERT_TRUE(spec) << spec.errors().front().to_string();
  ASSERT_EQ(spec->uber_shaders.size(), 2u);
  EXPECT_EQ(spec->uber_shaders[0].name, "raster");
  EXPECT_EQ(spec->uber_shaders[1].name, "compute");
  EXPECT_EQ(spec->uber_shaders[1].file.stage, Stage::compute);  // from the extension
  EXPECT_EQ(uber_shader_count(*spec), 2u);
  EXPECT_EQ(spec->uber.path, spec->uber_shaders[0].file.path);

  const DomainSpec raster = for_uber_shader(*spec, 0), compute = for_uber_shader(*spec, 1);
  EXPECT_EQ(raster.entry, "raster");
  EXPECT_EQ(raster.uber.path.filename(), "two.frag");
  ASSERT_EQ(raster.companions.size(), 1u);  // no "uber_shader": with the first entry
  EXPECT_EQ(raster.companions[0].name, "quad");
  EXPECT_EQ(compute.entry, "compute");
  EXPECT_EQ(compute.uber.path.filename(), "two.comp");
  ASSERT_EQ(compute.companions.size(), 1u);
  EXPECT_EQ(compute.companions[0].name, "prepass");
  // The features, rules and collapse are the domain's in both.
  EXPECT_EQ(raster.raw_features.size(), 2u);
  EXPECT_EQ(compute.ignored.size(), 1u);
}

TEST(UberShaders, WithoutThemTheSpecIsItsOwnOnlyEntry) {
  const std::string single = sgtest::replace_once(sgtest::replace_once(kBase, R"("uber_shaders": {
    "raster": { "path": "two.frag", "stage": "fragment" },
    "compute": { "path": "two.comp" }
  },)",
                                                                       R"("uber_shader": { "path": "two.frag" },)"),
                                                  R"(,
    { "name": "prepass", "uber_shader": "compute", "path": "prepass.comp" })",
                                                  "");
  auto spec = parse_domain(single, "spec.json");
  ASSERT_TRUE(spec) << spec.errors().front().to_string();
  EXPECT_TRUE(spec->uber_shaders.empty());
  EXPECT_EQ(uber_shader_count(*spec), 1u);
  const DomainSpec only = for_uber_shader(*spec, 0);
  EXPECT_TRUE(only.entry.empty());
  EXPECT_EQ(only.companions.size(), 1u);
}

class UberShaderErrors : public ::testing::TestWithParam<sgtest::SpecErrorCase> {};

TEST_P(UberShaderErrors, ExactDiagnostic) { EXPECT_EQ(sgtest::first_spec_error(GetParam().text), GetParam().expected); }

INSTANTIATE_TEST_SUITE_P(
    Table, UberShaderErrors,
    ::testing::Values(
        sgtest::SpecErrorCase{"and_uber_shader",
                              sgtest::replace_once(kBase, "\"format\": 1,", "\"format\": 1, \"uber_shader\": {},"),
                              "spec.json:4:19: error: uber_shaders: a spec has \"uber_shaders\" or \"uber_shader\", "
                              "not both"},
        sgtest::SpecErrorCase{"and_program",
                              sgtest::replace_once(kBase, "\"format\": 1,", "\"format\": 1, \"program\": {},"),
                              "spec.json:4:19: error: uber_shaders: a spec has \"uber_shaders\" or \"program\", "
                              "not both"},
        sgtest::SpecErrorCase{"empty",
                              sgtest::replace_once(kBase, R"({
    "raster": { "path": "two.frag", "stage": "fragment" },
    "compute": { "path": "two.comp" }
  })",
                                                   "{}"),
                              "spec.json:4:19: error: uber_shaders: expected 1 to 8 uber-shaders, each {\"path\", "
                              "\"stage\"}"},
        sgtest::SpecErrorCase{"keyword_name", sgtest::replace_once(kBase, "\"compute\": {", "\"class\": {"),
                              "spec.json:6:14: error: uber_shaders.class: \"class\" is a C++ keyword or reserved "
                              "name; the generated registry cannot declare it (an entry's name is the namespace of "
                              "its registry)"},
        sgtest::SpecErrorCase{"generated_name", sgtest::replace_once(kBase, "\"compute\": {", "\"companions\": {"),
                              "spec.json:6:19: error: uber_shaders.companions: \"companions\" is a name the "
                              "generated registry declares itself (an entry's name is the namespace of its "
                              "registry)"},
        sgtest::SpecErrorCase{"not_an_identifier", sgtest::replace_once(kBase, "\"compute\": {", "\"com-pute\": {"),
                              "spec.json:6:17: error: uber_shaders.com-pute: \"com-pute\" is not an identifier (an "
                              "entry's name is the namespace of its registry)"},
        sgtest::SpecErrorCase{
            "unknown_key",
            sgtest::replace_once(kBase, "{ \"path\": \"two.comp\" }", "{ \"path\": \"two.comp\", \"defines\": {} }"),
            "spec.json:6:49: error: uber_shaders.compute: unknown key \"defines\" (expected one of: "
            "path, stage)"},
        sgtest::SpecErrorCase{
            "companion_names_no_entry",
            sgtest::replace_once(kBase, "\"uber_shader\": \"compute\"", "\"uber_shader\": \"comput\""),
            "spec.json:10:41: error: companions[1].uber_shader: no uber-shader \"comput\" (the spec "
            "has raster, compute)"},
        sgtest::SpecErrorCase{"companion_keyword_name",
                              sgtest::replace_once(kBase, "\"name\": \"quad\"", "\"name\": \"default\""),
                              "spec.json:9:15: error: companions[0].name: \"default\" is a C++ keyword or reserved "
                              "name; the generated registry cannot declare it (a companion's name is its "
                              "accessor's)"}),
    [](const ::testing::TestParamInfo<sgtest::SpecErrorCase>& param_info) {
      return std::string(param_info.param.name);
    });

// A companion naming an entry in a spec without "uber_shaders".
TEST(UberShaders, ACompanionsUberShaderNeedsUberShaders) {
  const std::string single = sgtest::replace_once(kBase, R"("uber_shaders": {
    "raster": { "path": "two.frag", "stage": "fragment" },
    "compute": { "path": "two.comp" }
  },)",
                                                  R"("uber_shader": { "path": "two.frag" },)");
  EXPECT_EQ(sgtest::first_spec_error(single),
            "spec.json:7:41: error: companions[1].uber_shader: names an entry of \"uber_shaders\", and the spec has "
            "none");
}

// The fixture built: one manifest whose permutations are listed once, and per entry the blob
// of each; the two entries' blobs differ (a fragment and a compute shader of each permutation).
TEST(UberShaders, TheFixtureBuildsOneManifestWithEveryEntrysBlobs) {
  sgtest::TempDir out("uber_shaders_build");
  BuildOptions options;
  options.spec_path = std::filesystem::path(SHADERGEN_SOURCE_DIR) / "tests/fixtures/several_ubers/several_ubers.json";
  options.out_dir = out.path() / "out";
  options.use_cache = false;
  auto summary = build(options);
  ASSERT_TRUE(summary) << summary.errors().front().to_string();
  EXPECT_EQ(summary->raw, 8u);
  EXPECT_EQ(summary->pruned, 2u);
  EXPECT_EQ(summary->optimised, 5u);
  EXPECT_EQ(summary->companions, 3u);
  // Per entry: 6 raw + 5 optimised; companions 1 + 2.
  EXPECT_EQ(summary->permutations, 2u * (6u + 5u) + 3u);

  std::ifstream in(options.out_dir / "manifest.json");
  const nlohmann::json m = nlohmann::json::parse(in);
  EXPECT_FALSE(m.contains("uber_shader"));
  ASSERT_EQ(m["raw"].size(), 8u);
  for (const nlohmann::json& raw : m["raw"]) EXPECT_FALSE(raw.contains("spirv")) << raw.dump();
  ASSERT_EQ(m["uber_shaders"].size(), 2u);
  const nlohmann::json& raster = m["uber_shaders"][0];
  const nlohmann::json& compute = m["uber_shaders"][1];
  EXPECT_EQ(raster["name"], "raster");
  EXPECT_EQ(raster["stage"], "fragment");
  EXPECT_EQ(compute["name"], "compute");
  EXPECT_EQ(compute["stage"], "compute");
  for (const nlohmann::json* entry : {&raster, &compute}) {
    EXPECT_EQ((*entry)["raw"].size(), 6u);
    EXPECT_EQ((*entry)["optimised"].size(), 5u);
    for (const nlohmann::json& blob : (*entry)["optimised"])
      EXPECT_TRUE(std::filesystem::is_regular_file(options.out_dir / blob["spirv"].get<std::string>()));
  }
  for (std::size_t i = 0; i < 5; ++i) EXPECT_NE(raster["optimised"][i]["hash"], compute["optimised"][i]["hash"]) << i;
  ASSERT_EQ(raster["companions"].size(), 1u);
  EXPECT_EQ(raster["companions"][0]["name"], "full_screen");
  ASSERT_EQ(compute["companions"].size(), 2u);
  EXPECT_EQ(compute["companions"][0]["name"], "clear");
  // Each entry's layout is its own: the compute form's storage image is not the raster form's.
  EXPECT_EQ(raster["pipeline_layout"]["bindings"].size(), 1u);
  EXPECT_EQ(compute["pipeline_layout"]["bindings"].size(), 2u);
}

}  // namespace
}  // namespace uber_shaders_test
}  // namespace shadergen
