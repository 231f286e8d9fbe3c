// Target environments: `--target-env` (BuildOptions::target_env) and the spec key
// "target_env" pick the Vulkan version; the SPIR-V version follows it, every blob passes the
// external spirv-val for that environment, the manifest names it, and blobs compiled for one
// target are never taken from the cache for another.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstring>

#include "shadergen/build.h"
#include "shadergen/domain.h"
#include "test_helpers.h"

// A namespace of this file's own: the test executables are unity builds (tests/CMakeLists.txt).
namespace target_env_test {
namespace {

using nlohmann::json;
using sgtest::fs::path;

shadergen::Result<shadergen::BuildSummary> build_spec(const path& spec, const path& out, const path& cache,
                                                      const std::string& target_env) {
  shadergen::BuildOptions options = sgtest::build_options(spec, out, cache);
  options.target_env = target_env;
  return shadergen::build(options);
}

std::string first_error(const shadergen::Result<shadergen::BuildSummary>& result) {
  return result.ok() ? std::string() : result.errors().front().to_string();
}

// The version word (the second) of every blob of a build, by file name.
std::map<std::string, std::uint32_t> version_words(const path& out) {
  std::map<std::string, std::uint32_t> words;
  for (const auto& [name, bytes] : sgtest::snapshot(out / "spirv")) {
    std::uint32_t word = 0;
    if (bytes.size() >= 8) std::memcpy(&word, bytes.data() + 4, 4);
    words[name] = word;
  }
  return words;
}

struct TargetCase {
  const char* env;
  std::uint32_t version_word;  // SPIR-V version in the module header
};

void PrintTo(const TargetCase& c, std::ostream* os) { *os << c.env; }

class TargetEnvBuild : public ::testing::TestWithParam<TargetCase> {};

TEST_P(TargetEnvBuild, EveryBlobHasTheTargetsSpirvVersionAndPassesItsValidator) {
  const TargetCase& c = GetParam();
  sgtest::TempDir dir(std::string("target-") + c.env);
  auto summary = build_spec(sgtest::toy_spec(), dir / "out", dir / "cache", c.env);
  ASSERT_TRUE(summary.ok()) << first_error(summary);
  json manifest = json::parse(sgtest::read_file(dir / "out" / "manifest.json"));
  EXPECT_EQ(manifest["target_env"], c.env);
  auto words = version_words(dir / "out");
  ASSERT_EQ(words.size(), summary->unique_blobs);
  for (const auto& [name, word] : words) {
    SCOPED_TRACE(name);
    EXPECT_EQ(word, c.version_word);
    sgtest::ProcessResult val = sgtest::spirv_val(dir / "out" / "spirv" / name, c.env);
    EXPECT_EQ(val.exit_code, 0) << val.out << val.err;
  }
}

INSTANTIATE_TEST_SUITE_P(Envs, TargetEnvBuild,
                         ::testing::Values(TargetCase{"vulkan1.0", 0x00010000u}, TargetCase{"vulkan1.1", 0x00010300u},
                                           TargetCase{"vulkan1.2", 0x00010500u}, TargetCase{"vulkan1.3", 0x00010600u}),
                         [](const ::testing::TestParamInfo<TargetCase>& p) {
                           std::string name = p.param.env;
                           name.erase(name.find('.'), 1);
                           return name;
                         });

// The toy spec with "target_env" added, written next to a copy of its shaders.
path toy_copy_with_target(const sgtest::TempDir& dir, const std::string& env) {
  for (const auto& [name, bytes] : sgtest::snapshot(sgtest::toy_spec().parent_path()))
    sgtest::write_file(dir / ("spec/" + name), bytes);
  std::string text = sgtest::read_file(dir / "spec/toy.json");
  text.replace(text.find("\"format\": 1,"), 12, "\"format\": 1, \"target_env\": \"" + env + "\",");
  sgtest::write_file(dir / "spec/toy.json", text);
  return dir / "spec/toy.json";
}

TEST(TargetEnv, TheSpecKeyPicksTheTargetAndTheCommandLineWins) {
  sgtest::TempDir dir("target-spec-key");
  path spec = toy_copy_with_target(dir, "vulkan1.1");
  auto from_spec = build_spec(spec, dir / "spec-out", dir / "cache", "");
  ASSERT_TRUE(from_spec.ok()) << first_error(from_spec);
  for (const auto& [name, word] : version_words(dir / "spec-out")) EXPECT_EQ(word, 0x00010300u) << name;
  auto from_cli = build_spec(spec, dir / "cli-out", dir / "cache", "vulkan1.3");
  ASSERT_TRUE(from_cli.ok()) << first_error(from_cli);
  for (const auto& [name, word] : version_words(dir / "cli-out")) EXPECT_EQ(word, 0x00010600u) << name;
  EXPECT_EQ(json::parse(sgtest::read_file(dir / "cli-out" / "manifest.json"))["target_env"], "vulkan1.3");
}

// Same sources, same cache folder, another target: nothing may come from the first build.
TEST(TargetEnv, TheTargetIsPartOfTheCacheKey) {
  sgtest::TempDir dir("target-cache");
  auto old_target = build_spec(sgtest::toy_spec(), dir / "v10", dir / "cache", "vulkan1.0");
  ASSERT_TRUE(old_target.ok()) << first_error(old_target);
  auto new_target = build_spec(sgtest::toy_spec(), dir / "v13", dir / "cache", "vulkan1.3");
  ASSERT_TRUE(new_target.ok()) << first_error(new_target);
  EXPECT_FALSE(new_target->inputs_reused);
  EXPECT_EQ(new_target->cache_hits, 0u);
  EXPECT_EQ(new_target->compiled, new_target->unique_sources);
  auto again = build_spec(sgtest::toy_spec(), dir / "v10-again", dir / "cache", "vulkan1.0");
  ASSERT_TRUE(again.ok()) << first_error(again);
  EXPECT_TRUE(again->inputs_reused);
  EXPECT_EQ(again->compiled, 0u);
  EXPECT_EQ(sgtest::snapshot(dir / "v10-again"), sgtest::snapshot(dir / "v10"));
}

TEST(TargetEnv, AnUnknownTargetIsRefusedAndLeavesTheOutput) {
  sgtest::TempDir dir("target-bad");
  ASSERT_TRUE(build_spec(sgtest::toy_spec(), dir / "out", dir / "cache", "").ok());
  auto before = sgtest::snapshot(dir / "out");
  auto cli = build_spec(sgtest::toy_spec(), dir / "out", dir / "cache", "vulkan2.0");
  EXPECT_EQ(first_error(cli),
            "error: --target-env: unknown target environment \"vulkan2.0\" (expected vulkan1.0, vulkan1.1, "
            "vulkan1.2 or vulkan1.3)");
  path spec = toy_copy_with_target(dir, "opengl4.5");
  auto from_spec = build_spec(spec, dir / "out", dir / "cache", "");
  EXPECT_EQ(first_error(from_spec), spec.string() +
                                        ":2:30: error: target_env: unknown target environment \"opengl4.5\" (expected "
                                        "vulkan1.0, vulkan1.1, vulkan1.2 or vulkan1.3)");
  EXPECT_EQ(sgtest::snapshot(dir / "out"), before);
  sgtest::ProcessResult process = sgtest::run_process(
      sgtest::shadergen_exe(), {"build", sgtest::toy_spec().string(), "--out", (dir / "out").string(), "--cache-dir",
                                (dir / "cache").string(), "--target-env", "vulkan9"});
  EXPECT_EQ(process.exit_code, 1);
  EXPECT_EQ(process.err,
            "shadergen: error: --target-env: unknown target environment \"vulkan9\" (expected "
            "vulkan1.0, vulkan1.1, vulkan1.2 or vulkan1.3)\n");
  EXPECT_EQ(sgtest::snapshot(dir / "out"), before);
}

}  // namespace
}  // namespace target_env_test
