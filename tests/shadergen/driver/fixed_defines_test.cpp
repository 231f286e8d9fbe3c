// Fixed defines (tests/fixtures/fixed_defines): the spec's top-level "defines" reach the
// uber-shader and every companion, a companion's own value replaces the top-level one, and
// `--define` (BuildOptions::defines) adds to and replaces the spec's. The fixture's shaders
// #error without the fixed defines, size a push-constant block by MAX_LIGHTS and a work group
// by GROUP_SIZE, so each define's arrival is visible in the output.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstring>

#include "compile/reflection.h"
#include "shadergen/build.h"
#include "shadergen/cli.h"
#include "shadergen/domain.h"
#include "test_helpers.h"

// A namespace of this file's own: the test executables are unity builds (tests/CMakeLists.txt).
namespace fixed_defines_test {
namespace {

using nlohmann::json;
using sgtest::fs::path;

path fixed_spec() { return sgtest::fixtures_dir() / "fixed_defines" / "fixed_defines.json"; }

shadergen::Result<shadergen::BuildSummary> build_fixed(const path& out, const path& cache,
                                                       std::vector<std::string> defines = {}) {
  shadergen::BuildOptions options = sgtest::build_options(fixed_spec(), out, cache);
  options.defines = std::move(defines);
  return shadergen::build(options);
}

std::string first_error(const shadergen::Result<shadergen::BuildSummary>& result) {
  return result.ok() ? std::string() : result.errors().front().to_string();
}

json manifest_of(const path& out) { return json::parse(sgtest::read_file(out / "manifest.json")); }

std::uint32_t push_constant_size(const json& manifest) {
  const json& ranges = manifest["pipeline_layout"]["push_constants"];
  return ranges.empty() ? 0u : ranges[0]["size"].get<std::uint32_t>();
}

// The work-group width of companion `name`, reflected from its blob on disk.
std::uint32_t group_width(const path& out, const json& manifest, const std::string& name) {
  for (const json& companion : manifest["companions"]) {
    if (companion["name"] != name) continue;
    std::string bytes = sgtest::read_file(out / companion["spirv"].get<std::string>());
    std::vector<std::uint32_t> words(bytes.size() / 4);
    std::memcpy(words.data(), bytes.data(), words.size() * 4);
    auto info = shadergen::reflect(words, shadergen::Stage::compute);
    return info ? info->local_size[0] : 0u;
  }
  return 0u;
}

TEST(FixedDefines, SpecReadsTopLevelAndCompanionDefinesInOrder) {
  auto spec = shadergen::load_domain(fixed_spec());
  ASSERT_TRUE(spec.ok()) << spec.errors().front().to_string();
  EXPECT_EQ(spec->defines,
            (std::vector<std::string>{"STAGE_FRAGMENT=1", "RENDERER_FORWARD=1", "MAX_LIGHTS=4", "GROUP_SIZE=64"}));
  ASSERT_EQ(spec->companions.size(), 2u);
  EXPECT_EQ(spec->companions[0].defines, (std::vector<std::string>{"GROUP_SIZE=256"}));
  EXPECT_EQ(spec->companions[1].defines, (std::vector<std::string>{"PREPASS"}));
}

TEST(FixedDefines, ReachEveryShaderAndACompanionsOwnValueWins) {
  sgtest::TempDir dir("fixed-defines");
  auto summary = build_fixed(dir / "out", dir / "cache");
  ASSERT_TRUE(summary.ok()) << first_error(summary);
  json manifest = manifest_of(dir / "out");
  EXPECT_EQ(push_constant_size(manifest), 4u * 16u) << "MAX_LIGHTS=4 vec4 colours";
  EXPECT_EQ(group_width(dir / "out", manifest, "cull"), 256u) << "the companion's own GROUP_SIZE";
  EXPECT_EQ(group_width(dir / "out", manifest, "prepass"), 64u) << "the top-level GROUP_SIZE";
  // Fixed defines are settings of the build, not of a permutation: the lists stay the features'.
  EXPECT_EQ(manifest["raw"][1]["defines"], json::array({"HAS_FOG"}));
  EXPECT_EQ(manifest["raw"][0]["defines"], json::array());
  EXPECT_EQ(manifest["companions"][0]["defines"], json::array({"GROUP_SIZE=256"}));
  // ...and the manifest records them once, for the whole build.
  EXPECT_EQ(manifest["defines"],
            json::array({"STAGE_FRAGMENT=1", "RENDERER_FORWARD=1", "MAX_LIGHTS=4", "GROUP_SIZE=64"}));
}

TEST(FixedDefines, CommandLineDefinesAddToAndReplaceTheSpecs) {
  sgtest::TempDir dir("fixed-defines-cli");
  auto summary = build_fixed(dir / "out", dir / "cache", {"MAX_LIGHTS=8", "GROUP_SIZE=32", "EXTRA"});
  ASSERT_TRUE(summary.ok()) << first_error(summary);
  json manifest = manifest_of(dir / "out");
  EXPECT_EQ(push_constant_size(manifest), 8u * 16u);
  EXPECT_EQ(group_width(dir / "out", manifest, "prepass"), 32u);
  EXPECT_EQ(group_width(dir / "out", manifest, "cull"), 256u) << "a companion's own define still wins";
  EXPECT_EQ(manifest["defines"],
            json::array({"STAGE_FRAGMENT=1", "RENDERER_FORWARD=1", "MAX_LIGHTS=8", "GROUP_SIZE=32", "EXTRA=1"}));
}

// The input-set cache maps unchanged files straight to content keys; a build with other
// --define values reads the same files, so it must not take the keys of the first.
TEST(FixedDefines, ADifferentCommandLineValueNeverReusesStalePreprocessing) {
  sgtest::TempDir dir("fixed-defines-stale");
  auto four = build_fixed(dir / "four", dir / "cache", {"MAX_LIGHTS=4"});
  ASSERT_TRUE(four.ok()) << first_error(four);
  auto eight = build_fixed(dir / "eight", dir / "cache", {"MAX_LIGHTS=8"});
  ASSERT_TRUE(eight.ok()) << first_error(eight);
  EXPECT_FALSE(eight->inputs_reused);
  EXPECT_EQ(eight->compiled, 2u) << "the two uber-shader sources change; the companions' do not";
  EXPECT_EQ(push_constant_size(manifest_of(dir / "eight")), 8u * 16u);
  auto again = build_fixed(dir / "again", dir / "cache", {"MAX_LIGHTS=4"});
  ASSERT_TRUE(again.ok()) << first_error(again);
  EXPECT_TRUE(again->inputs_reused) << "the first build's input set is still there, under its own key";
  EXPECT_EQ(again->compiled, 0u);
  EXPECT_EQ(sgtest::snapshot(dir / "again"), sgtest::snapshot(dir / "four"));
}

// A define no shader tests changes no preprocessed text, so every blob comes from the cache
// and the SPIR-V and the generated source are byte for byte the plain build's; only the
// records of the fixed defines (the manifest's "defines", the header's kDefines) name it.
TEST(FixedDefines, AnUnusedCommandLineDefineChangesOnlyTheRecordOfTheDefines) {
  sgtest::TempDir dir("fixed-defines-unused");
  auto plain = build_fixed(dir / "plain", dir / "cache");
  ASSERT_TRUE(plain.ok()) << first_error(plain);
  auto unused = build_fixed(dir / "unused", dir / "cache", {"NOBODY_READS_THIS=7"});
  ASSERT_TRUE(unused.ok()) << first_error(unused);
  EXPECT_EQ(unused->compiled, 0u);
  EXPECT_EQ(unused->cache_hits, unused->unique_sources);
  auto unused_files = sgtest::snapshot(dir / "unused"), plain_files = sgtest::snapshot(dir / "plain");
  for (const char* recorded : {"manifest.json", "fixed_defines.h"}) {
    EXPECT_TRUE(sgtest::contains(unused_files[recorded], "NOBODY_READS_THIS")) << recorded;
    unused_files.erase(recorded);
    plain_files.erase(recorded);
  }
  EXPECT_EQ(unused_files, plain_files) << sgtest::describe_difference(unused_files, plain_files);
}

TEST(FixedDefines, BadCommandLineDefinesAreRefusedAndLeaveTheOutput) {
  sgtest::TempDir dir("fixed-defines-bad");
  ASSERT_TRUE(build_fixed(dir / "out", dir / "cache").ok());
  auto before = sgtest::snapshot(dir / "out");
  struct Case {
    std::string argument;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {"1X=2", "error: --define 1X=2: \"1X\" is not an identifier ([A-Za-z_][A-Za-z0-9_]*, at most 64)"},
      {"=3", "error: --define =3: \"\" is not an identifier ([A-Za-z_][A-Za-z0-9_]*, at most 64)"},
      {"GL_FOO", "error: --define GL_FOO: \"GL_FOO\" is reserved by GLSL (a GL_ prefix or a double underscore)"},
      {"A=x\ny",
       "error: --define A=x\ny: the value holds a line break or another control character; it must "
       "fit on the #define line"},
      {"HAS_FOG=1", "error: --define HAS_FOG=1: HAS_FOG is the define of raw feature FOG of " + fixed_spec().string() +
                        "; a fixed define cannot also be a feature"},
  };
  for (const Case& c : cases) {
    auto result = build_fixed(dir / "out", dir / "cache", {c.argument});
    EXPECT_EQ(first_error(result), c.expected) << c.argument;
  }
  EXPECT_EQ(sgtest::snapshot(dir / "out"), before);
}

TEST(FixedDefines, TheCliTakesRepeatedDefineOptions) {
  sgtest::TempDir dir("fixed-defines-process");
  sgtest::ProcessResult r = sgtest::run_process(
      sgtest::shadergen_exe(), {"build", fixed_spec().string(), "--out", (dir / "out").string(), "--cache-dir",
                                (dir / "cache").string(), "--define", "MAX_LIGHTS=2", "--define", "GROUP_SIZE=16"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  json manifest = manifest_of(dir / "out");
  EXPECT_EQ(push_constant_size(manifest), 2u * 16u);
  EXPECT_EQ(group_width(dir / "out", manifest, "prepass"), 16u);
  sgtest::ProcessResult bad =
      sgtest::run_process(sgtest::shadergen_exe(), {"build", fixed_spec().string(), "--out", (dir / "out").string(),
                                                    "--cache-dir", (dir / "cache").string(), "--define", "9=1"});
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_EQ(bad.err,
            "shadergen: error: --define 9=1: \"9\" is not an identifier ([A-Za-z_][A-Za-z0-9_]*, at most 64)\n");
  EXPECT_EQ(push_constant_size(manifest_of(dir / "out")), 2u * 16u) << "the failed run left the output";
}

}  // namespace
}  // namespace fixed_defines_test
