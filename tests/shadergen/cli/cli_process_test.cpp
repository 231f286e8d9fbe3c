// The shadergen executable as a process, the way a user and CMake meet it: exit statuses
// (0 success, 1 input or build error, 2 usage), what goes to stdout and what to stderr, the
// lut/list/explain views and a build. Complements the in-process run_cli tests: this runs
// main() itself.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "test_helpers.h"

namespace {

using sgtest::ProcessResult;

ProcessResult shadergen_run(const std::vector<std::string>& args) {
  return sgtest::run_process(sgtest::shadergen_exe(), args);
}

TEST(CliProcess, HelpExitsZeroAndNamesEverySubcommand) {
  ProcessResult r = shadergen_run({"--help"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  for (const char* word : {"build", "lut", "list", "explain", "--version"})
    EXPECT_TRUE(sgtest::contains(r.out, word)) << word << " missing from:\n" << r.out;
}

TEST(CliProcess, VersionPrintsNameAndVersion) {
  ProcessResult r = shadergen_run({"--version"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out.rfind("shadergen 0.1.0 (glslang ", 0), 0u) << r.out;
  EXPECT_TRUE(sgtest::contains(r.out, ", SPIRV-Tools ")) << r.out;
  EXPECT_TRUE(sgtest::contains(r.out, ", SPIRV-Cross C API ")) << r.out;
}

TEST(CliProcess, UsageErrorsExitTwo) {
  struct Case {
    const char* what;
    std::vector<std::string> args;
  };
  const std::vector<Case> cases = {
      {"no subcommand", {}},
      {"unknown option alone", {"--frobnicate"}},
      {"unknown option", {"--frobnicate", "lut", sgtest::toy_spec().string()}},
      {"unknown subcommand", {"frobnicate"}},
      {"unknown build option", {"build", sgtest::toy_spec().string(), "--out", "x", "--frobnicate"}},
      {"build without --out", {"build", sgtest::toy_spec().string()}},
      {"-j out of range", {"build", sgtest::toy_spec().string(), "--out", "x", "-j", "0"}},
      {"explain without an ID", {"explain", sgtest::toy_spec().string()}},
  };
  for (const Case& c : cases) {
    ProcessResult r = shadergen_run(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.what << "\nstdout: " << r.out << "\nstderr: " << r.err;
    EXPECT_FALSE(r.err.empty()) << c.what << ": a usage error must say what is wrong on stderr";
  }
  EXPECT_FALSE(sgtest::fs::exists("x")) << "a usage error must not build anything";
  ProcessResult unknown = shadergen_run({"lut", "--frobnicate", sgtest::toy_spec().string()});
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_TRUE(sgtest::contains(unknown.err, "--frobnicate")) << "the message names the option:\n" << unknown.err;
}

TEST(CliProcess, LutPrintsTheSixteenColumnGrid) {
  ProcessResult r = shadergen_run({"lut", sgtest::split_second_spec().string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(sgtest::contains(r.out, "Domain split_second: 128 raw IDs -> 32 optimised IDs\n")) << r.out;
  EXPECT_TRUE(sgtest::contains(r.out, "\n         0   1   2   3   4   5   6   7   8   9  10  11  12  13  14  15\n"))
      << r.out;
  // Every row of the grid, exactly (Listing 4.8 with the brace fixed; -- = pruned).
  for (const char* row : {
           "   0:    0   0   0  --   0   0   0  --   1   1   1  --   1   1   1  --\n",
           "  16:    2   2   2  --   2   2   2  --   3   3   3  --   3   3   3  --\n",
           "  32:    4   4   4  --   4   4   4  --   5   5   5  --   5   5   5  --\n",
           "  48:    6   6   6  --   6   6   6  --   7   7   7  --   7   7   7  --\n",
           "  64:   16   0  24  --  16   8  24  --  17   1  25  --  17   9  25  --\n",
           "  80:   18   2  26  --  18  10  26  --  19   3  27  --  19  11  27  --\n",
           "  96:   20   4  28  --  20  12  28  --  21   5  29  --  21  13  29  --\n",
           " 112:   22   6  30  --  22  14  30  --  23   7  31  --  23  15  31  --\n",
       })
    EXPECT_TRUE(sgtest::contains(r.out, row)) << row << "missing from:\n" << r.out;
  EXPECT_TRUE(r.err.empty()) << r.err;
}

TEST(CliProcess, LutOfTheToyDomainIsOneRow) {
  ProcessResult r = shadergen_run({"lut", sgtest::toy_spec().string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(sgtest::contains(r.out, "   0:    0   1   2   3   2   3   2   3   1  --   3  --   3  --   3  --\n"))
      << r.out;
  EXPECT_FALSE(sgtest::contains(r.out, "  16:")) << r.out;
}

TEST(CliProcess, ListCountsThePermutations) {
  ProcessResult r = shadergen_run({"list", sgtest::split_second_spec().string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(sgtest::contains(r.out, "raw permutations: 128 (32 pruned, 96 compiled)")) << r.out;
  EXPECT_TRUE(sgtest::contains(r.out, "optimised permutations: 32")) << r.out;
}

TEST(CliProcess, ExplainNamesTheOptimisedId) {
  struct Case {
    const char* raw;
    const char* expected;
  };
  for (const Case& c : {Case{"69", "-> optimised ID 8 = SUN_0"}, Case{"0x45", "-> optimised ID 8 = SUN_0"},
                        Case{"SHADOW_SOLID|SHADOW_FADE|SUN_LIGHT", "-> optimised ID 8 = SUN_0"},
                        Case{"65", "-> optimised ID 0 = (none)\n"}, Case{"64", "-> optimised ID 16 = SUN_1"},
                        Case{"66", "-> optimised ID 24 = SUN_0 | SUN_1"},
                        Case{"126", "-> optimised ID 31 = LIGHT_SCATTERING | MSAA_EDGE | SKY | SUN_0 | SUN_1"}}) {
    ProcessResult r = shadergen_run({"explain", sgtest::split_second_spec().string(), c.raw});
    EXPECT_EQ(r.exit_code, 0) << c.raw << ": " << r.err;
    EXPECT_TRUE(sgtest::contains(r.out, c.expected)) << c.raw << ":\n" << r.out;
  }
  ProcessResult r = shadergen_run({"explain", sgtest::split_second_spec().string(), "69"});
  EXPECT_TRUE(sgtest::contains(r.out, "raw ID 69 = SHADOW_SOLID | SHADOW_FADE | SUN_LIGHT\n")) << r.out;
}

TEST(CliProcess, ExplainOfAPrunedIdSaysWhichRulePrunesIt) {
  ProcessResult r = shadergen_run({"explain", sgtest::split_second_spec().string(), "127"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(sgtest::contains(r.out, "pruned: it matches the impossible rule \"SHADOW_SOLID && SHADOW_SOFT\""))
      << r.out;
}

TEST(CliProcess, ExplainRejectsABadRawIdNamingTheValue) {
  const std::string spec = sgtest::split_second_spec().string();
  struct Case {
    const char* raw;
    const char* message;
  };
  for (const Case& c : {
           Case{"128", "shadergen: error: raw ID 128 is out of range: domain split_second has raw IDs 0 to 127\n"},
           Case{"0x80", "shadergen: error: raw ID 0x80 is out of range: domain split_second has raw IDs 0 to 127\n"},
           Case{"NOT_A_FEATURE",
                "shadergen: error: unknown feature \"NOT_A_FEATURE\" (known: SHADOW_SOLID, SHADOW_SOFT, "
                "SHADOW_FADE, LIGHT_SCATTERING, MSAA_EDGE, SKY, SUN_LIGHT)\n"},
           Case{"SKY|SOFT_SHADOW",
                "shadergen: error: \"SOFT_SHADOW\" is the define of feature SHADOW_SOFT; name the feature\n"},
           Case{"SKY=1",
                "shadergen: error: feature SKY is a boolean: write SKY alone, or leave it out (SKY=1 is not "
                "accepted)\n"},
       }) {
    ProcessResult r = shadergen_run({"explain", spec, c.raw});
    EXPECT_EQ(r.exit_code, 2) << c.raw;
    EXPECT_EQ(r.err, c.message) << c.raw;
    EXPECT_TRUE(r.out.empty()) << c.raw << ": " << r.out;
  }
}

TEST(CliProcess, MissingSpecExitsOneNamingThePath) {
  sgtest::TempDir dir("cli-missing");
  const std::string missing = (dir / "no_such_spec.json").string();
  for (const char* command : {"lut", "list"}) {
    ProcessResult r = shadergen_run({command, missing});
    EXPECT_EQ(r.exit_code, 1) << command;
    EXPECT_EQ(r.err, missing + ": error: spec file does not exist\n") << command;
  }
  ProcessResult build =
      shadergen_run({"build", missing, "--out", (dir / "out").string(), "--cache-dir", (dir / "cache").string()});
  EXPECT_EQ(build.exit_code, 1);
  EXPECT_EQ(build.err, missing + ": error: spec file does not exist\n");
  EXPECT_FALSE(sgtest::fs::exists(dir / "out"));
}

TEST(CliProcess, BuildWithABitCollisionExitsOneNamingFileAndLine) {
  sgtest::TempDir dir("cli-collision");
  // The fixture's FOG (raw.features[2]) has LIT's bit; the error points at the value, line 10.
  const std::string file = (sgtest::fixtures_dir() / "bit_collision" / "bit_collision.json").string();
  ProcessResult r =
      shadergen_run({"build", file, "--out", (dir / "out").string(), "--cache-dir", (dir / "cache").string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, file + ":10:36: error: raw.features[2].bit: bit 0 of FOG collides with feature LIT\n");
  EXPECT_FALSE(sgtest::fs::exists(dir / "out"));
  EXPECT_FALSE(sgtest::fs::exists(dir / "cache")) << "nothing is compiled for an invalid spec";
}

TEST(CliProcess, BuildPrintsASummaryOnStdoutAndWritesTheOutput) {
  sgtest::TempDir dir("cli-build");
  const std::vector<std::string> args = {"build",       sgtest::toy_spec().string(), "--out", (dir / "out").string(),
                                         "--cache-dir", (dir / "cache").string(),    "-j",    "2"};
  ProcessResult first = shadergen_run(args);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_TRUE(sgtest::contains(first.out,
                               ": 16 raw (4 pruned), 4 optimised, 1 companion -> 13 distinct sources "
                               "(13 compiled, 0 cached), 13 SPIR-V blobs in "))
      << first.out;
  auto manifest = nlohmann::json::parse(sgtest::read_file(dir / "out" / "manifest.json"));
  EXPECT_EQ(manifest["raw"].size(), 16u);

  ProcessResult second = shadergen_run(args);
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_TRUE(sgtest::contains(second.out, "(0 compiled, 13 cached), 13 SPIR-V blobs; output unchanged in "))
      << second.out;
}

// What a new user hit (issue 51): a one-word kind change renumbers the optimised IDs, and the
// summary says so; a branch_block left without a branch is a warning on stderr, not an error.
TEST(CliProcess, BuildNotesRenumberedOptimisedIdsAndWarnsOfAnUnusedBranchBlock) {
  sgtest::TempDir dir("cli-renumbered");
  const std::string shader = (sgtest::fixtures_dir() / "kinds" / "kinds.frag").string();
  auto spec = [&](const std::string& soft_kind) {
    return R"({"format": 1, "name": "m", "uber_shader": {"path": ")" + shader + R"("}, "define_style": "value",
  "raw": {"features": [{"name": "FOG", "bit": 0, "define": "FOG"},
    {"name": "SOFT", "bit": 1, "define": "SOFT", "kind": ")" +
           soft_kind + R"("}, {"name": "TAPS", "bit": 2, "define": "TAPS", "values": [1, 4, 8]},
    {"name": "SHADING", "bit": 4, "define": "SHADING", "values": ["UNLIT", "PBR"]}],
    "impossible": [{"when": "SHADING == UNLIT && SOFT"}]},
  "branch_block": {"set": 1, "binding": 0},
  "optimised": {"ignore": [{"feature": "TAPS"}]}})";
  };
  const std::vector<std::string> args = {"build",       (dir / "m.json").string(), "--out", (dir / "out").string(),
                                         "--cache-dir", (dir / "cache").string()};
  sgtest::write_file(dir / "m.json", spec("variant"));
  ProcessResult first = shadergen_run(args);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_TRUE(sgtest::contains(first.err, (dir / "m.json").string() +
                                              ":6:19: warning: branch_block: no feature is of kind branch, so no "
                                              "block is declared; remove it, or make a feature a branch\n"))
      << first.err;
  EXPECT_FALSE(sgtest::contains(first.out, "note:")) << first.out;

  sgtest::write_file(dir / "m.json", spec("specialization"));
  ProcessResult second = shadergen_run(args);
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_TRUE(sgtest::contains(second.out, (dir / "out").string() +
                                               ": note: 6 raw IDs map to other optimised IDs than in the previous "
                                               "output (feature kinds changed: SOFT (variant -> specialization)); "
                                               "anything keyed by optimised ID (a pipeline cache) is stale\n"))
      << second.out;
}

}  // namespace
