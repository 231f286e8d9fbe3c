// The CLI as a user meets it: exit codes, messages on stderr, grouped GLSL errors, and a failed
// build that leaves the previous output exactly as it was.
#include <gtest/gtest.h>

#include <glslang/build_info.h>
#include <spirv-tools/libspirv.h>
#include <spirv_cross/spirv_cross_c.h>

#include <sstream>

#include "shadergen/cli.h"
#include "test_helpers.h"

namespace shadergen {
namespace {

namespace fs = std::filesystem;

struct CliRun {
  int code;
  std::string out;
  std::string err;
};

CliRun cli(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  int code = run_cli(args, out, err);
  return {code, out.str(), err.str()};
}

TEST(Cli, HelpListsTheSubcommands) {
  CliRun r = cli({"--help"});
  EXPECT_EQ(r.code, 0);
  for (const char* word : {"build", "lut", "list", "explain", "--version"})
    EXPECT_NE(r.out.find(word), std::string::npos) << word;
}

TEST(Cli, BuildHelpDocumentsItsOptions) {
  CliRun r = cli({"build", "--help"});
  EXPECT_EQ(r.code, 0);
  for (const char* word : {"--out", "--no-cache", "--cache-dir", "--depfile", "-j", "--stats", "-v"})
    EXPECT_NE(r.out.find(word), std::string::npos) << word;
}

// The compiler libraries make the blobs, so the version names them too.
TEST(Cli, Version) {
  CliRun r = cli({"--version"});
  EXPECT_EQ(r.code, 0);
  std::string glslang = std::to_string(GLSLANG_VERSION_MAJOR) + "." + std::to_string(GLSLANG_VERSION_MINOR) + "." +
                        std::to_string(GLSLANG_VERSION_PATCH) + GLSLANG_VERSION_FLAVOR;
  std::string cross = std::to_string(SPVC_C_API_VERSION_MAJOR) + "." + std::to_string(SPVC_C_API_VERSION_MINOR) + "." +
                      std::to_string(SPVC_C_API_VERSION_PATCH);
  EXPECT_EQ(r.out, "shadergen " SHADERGEN_VERSION_STRING " (glslang " + glslang + ", SPIRV-Tools " +
                       spvSoftwareVersionString() + ", SPIRV-Cross C API " + cross + ")\n");
}

// A misspelt subcommand or option is named with the one meant, on stderr, exit 2.
TEST(Cli, MisspeltNamesSuggestTheMeantOne) {
  const std::string spec = sgtest::toy_spec().string();
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"biuld", spec}, "shadergen: error: unknown subcommand 'biuld'; did you mean 'build'?\n"},
      {{"explian", spec, "1"}, "shadergen: error: unknown subcommand 'explian'; did you mean 'explain'?\n"},
      {{"frobnicate"}, "shadergen: error: unknown subcommand 'frobnicate' (subcommands: build, lut, list, explain)\n"},
      {{"build", spec, "--output", "x"},
       "shadergen: error: unknown option '--output' for 'build'; did you mean '--out'?\n"},
      {{"build", spec, "--out=x", "--no-cahce"},
       "shadergen: error: unknown option '--no-cahce' for 'build'; did you mean '--no-cache'?\n"},
      {{"build", spec, "--out", "x", "--strip"},
       "shadergen: error: unknown option '--strip' for 'build'; did you mean '--strip-debug'?\n"},
      {{"lut", spec, "--frobnicate"}, "shadergen: error: unknown option '--frobnicate' for 'lut'\n"},
  };
  for (const auto& [args, message] : cases) {
    CliRun r = cli(args);
    EXPECT_EQ(r.code, 2) << args[0];
    EXPECT_EQ(r.err, message);
    EXPECT_EQ(r.out, "");
  }
}

TEST(Cli, UsageErrorsExitTwo) {
  EXPECT_EQ(cli({}).code, 2);
  EXPECT_EQ(cli({"frobnicate"}).code, 2);
  EXPECT_EQ(cli({"build", sgtest::toy_spec().string()}).code, 2) << "--out is required";
  EXPECT_EQ(cli({"build", sgtest::toy_spec().string(), "--out", "x", "-j", "0"}).code, 2);
}

TEST(Cli, LutPrintsTheGrid) {
  CliRun r = cli({"lut", sgtest::split_second_spec().string()});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("  64:   16   0  24  --  16   8  24  --  17   1  25  --  17   9  25  --"), std::string::npos)
      << r.out;
}

TEST(Cli, ListNamesEveryPermutation) {
  CliRun r = cli({"list", sgtest::split_second_spec().string()});
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("raw permutations: 128 (32 pruned, 96 compiled)"), std::string::npos);
  EXPECT_NE(r.out.find("optimised permutations: 32"), std::string::npos);
}

TEST(Cli, ExplainAcceptsNumbersAndNames) {
  const std::string spec = sgtest::split_second_spec().string();
  CliRun by_number = cli({"explain", spec, "69"});
  EXPECT_EQ(by_number.code, 0);
  EXPECT_NE(by_number.out.find("-> optimised ID 8"), std::string::npos) << by_number.out;
  // A whole argument that is a number is the raw ID; anything else is read in the grammar of
  // shadergen::parse_combination().
  for (const char* same :
       {"0x45", "0b1000101", " 69 ", "SHADOW_SOLID|SHADOW_FADE|SUN_LIGHT", " SUN_LIGHT |\tSHADOW_FADE| SHADOW_SOLID"}) {
    CliRun r = cli({"explain", spec, same});
    EXPECT_EQ(r.code, 0) << same << ": " << r.err;
    EXPECT_EQ(r.out, by_number.out) << same;
  }
  CliRun none = cli({"explain", spec, "(none)"});
  EXPECT_EQ(none.code, 0) << none.err;
  EXPECT_EQ(none.out, cli({"explain", spec, "0"}).out);
}

// Every refusal is a usage error (2) whose one line names the offending word.
TEST(Cli, ExplainRejectsBadIdsNamingTheWord) {
  const std::string split_second = sgtest::split_second_spec().string();
  const std::string valued = (sgtest::fixtures_dir() / "valued" / "valued.json").string();
  const std::string known =
      " (known: SHADOW_SOLID, SHADOW_SOFT, SHADOW_FADE, LIGHT_SCATTERING, MSAA_EDGE, SKY, SUN_LIGHT)";
  struct Case {
    const std::string& spec;
    std::string raw;
    std::string message;
  };
  const Case cases[] = {
      {split_second, "128", "raw ID 128 is out of range: domain split_second has raw IDs 0 to 127"},
      {split_second, "0x80", "raw ID 0x80 is out of range: domain split_second has raw IDs 0 to 127"},
      {split_second, "99999999999999999999999",
       "raw ID 99999999999999999999999 is out of range: domain split_second has raw IDs 0 to 127"},
      {split_second, "SKY|MOON", "unknown feature \"MOON\"" + known},
      {split_second, "12abc", "unknown feature \"12abc\"" + known},
      {split_second, "SKY+SUN_LIGHT", "unknown feature \"SKY+SUN_LIGHT\"" + known},
      {split_second, "SKY|12", "\"12\" is a number; name the features instead, joined by '|'"},
      {split_second, "SOFT_SHADOW|SUN_LIGHT", "\"SOFT_SHADOW\" is the define of feature SHADOW_SOFT; name the feature"},
      {split_second, "MSAA_EDGE=1",
       "feature MSAA_EDGE is a boolean: write MSAA_EDGE alone, or leave it out (MSAA_EDGE=1 is not accepted)"},
      {split_second, "SKY=0", "feature SKY is a boolean: write SKY alone, or leave it out (SKY=0 is not accepted)"},
      {split_second, "SKY||SUN_LIGHT", "an empty word at offset 4: two '|' in a row, or one at the start or the end"},
      {split_second, "SKY|SUN_LIGHT|SKY", "feature SKY is named twice (again as \"SKY\"); name each feature once"},
      {valued, "TAA_QUALITY=7", "TAA_QUALITY has no value \"7\" (values: 0, 1, 2)"},
      {valued, "SHARPEN|TAA_QUALITY", "feature TAA_QUALITY takes a value: write TAA_QUALITY=<value> (values: 0, 1, 2)"},
  };
  for (const Case& c : cases) {
    CliRun r = cli({"explain", c.spec, c.raw});
    EXPECT_EQ(r.code, 2) << c.raw;
    EXPECT_EQ(r.err, "shadergen: error: " + c.message + "\n") << c.raw;
    EXPECT_TRUE(r.out.empty()) << c.raw << ": " << r.out;
  }
}

TEST(Cli, MissingSpecNamesThePath) {
  CliRun r = cli({"lut", "/no/such/spec.json"});
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, "/no/such/spec.json: error: spec file does not exist\n");
}

TEST(Cli, BitCollisionNamesFileAndLine) {
  sgtest::TempDir collision_dir("collision");
  const fs::path& dir = collision_dir.path();
  std::string spec = sgtest::read_file(sgtest::toy_spec());
  spec.replace(spec.find("\"bit\": 3"), 8, "\"bit\": 0");
  sgtest::write_file(dir / "toy.json", spec);
  CliRun r = cli({"build", (dir / "toy.json").string(), "--out", (dir / "out").string(), "--no-cache"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("toy.json:15:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("error: raw.features[3].bit: bit 0 of DISTORT collides with feature LIT"), std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

// A GLSL error inside one feature's #ifdef is reported once, at its original file and line,
// naming the permutations it occurs in; the previous output is left exactly as it was.
TEST(Cli, GlslErrorInsideOneFeatureKeepsThePreviousOutput) {
  sgtest::TempDir glsl_error_dir("glsl_error");
  const fs::path& dir = glsl_error_dir.path();
  fs::copy(sgtest::toy_spec().parent_path(), dir / "domain", fs::copy_options::recursive);
  fs::path out = dir / "out";
  std::string cache = (dir / "cache").string();
  ASSERT_EQ(cli({"build", (dir / "domain" / "toy.json").string(), "--out", out.string(), "--cache-dir", cache}).code,
            0);
  auto before = sgtest::snapshot(out);
  auto time_before = fs::last_write_time(out / "manifest.json");

  std::string shader = sgtest::read_file(dir / "domain" / "particle.frag");
  std::string good = "    color.a *= clamp((scene - gl_FragCoord.z) * 50.0, 0.0, 1.0);";
  ASSERT_NE(shader.find(good), std::string::npos);
  shader.replace(shader.find(good), good.size(), "    color.a *= clamp((scene - fragment_depth) * 50.0, 0.0, 1.0);");
  sgtest::write_file(dir / "domain" / "particle.frag", shader);

  CliRun r = cli({"build", (dir / "domain" / "toy.json").string(), "--out", out.string(), "--cache-dir", cache});
  EXPECT_EQ(r.code, 1);
  std::size_t errors = 0;
  for (std::size_t at = r.err.find("error:"); at != std::string::npos; at = r.err.find("error:", at + 1)) ++errors;
  EXPECT_EQ(errors, 1u) << "one grouped error, no follow-on noise:\n" << r.err;
  std::string file = (dir / "domain" / "particle.frag").lexically_normal().string();
  EXPECT_NE(r.err.find(file + ":19: error: 'fragment_depth' : undeclared identifier (in 6 of 12 raw permutations: "
                              "those with SOFT [SOFT_PARTICLES]; 2 of 4 optimised permutations; e.g. raw 4 with "
                              "SOFT_PARTICLES)"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(sgtest::snapshot(out), before);
  EXPECT_EQ(fs::last_write_time(out / "manifest.json"), time_before);
  for (const auto& entry : fs::directory_iterator(dir))
    EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos) << "left behind: " << entry.path();
}

TEST(Cli, BuildPrintsASummaryAndWritesADepfile) {
  sgtest::TempDir depfile_dir("depfile");
  const fs::path& dir = depfile_dir.path();
  CliRun r = cli({"build", sgtest::toy_spec().string(), "--out", (dir / "out").string(), "--cache-dir",
                  (dir / "cache").string(), "--depfile", (dir / "toy.d").string()});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("16 raw (4 pruned), 4 optimised, 1 companion"), std::string::npos) << r.out;
  std::string depfile = sgtest::read_file(dir / "toy.d");
  EXPECT_EQ(depfile.rfind((dir / "out" / "toy_particles.h").string() + ":", 0), 0u) << depfile;
  for (const char* dep : {"toy.json", "particle.frag", "particle_common.glsl", "sort.comp"})
    EXPECT_NE(depfile.find(dep), std::string::npos) << dep;
}

}  // namespace
}  // namespace shadergen
