// A GLSL error inside one feature's #ifdef (tests/fixtures/glsl_error: the toy domain with
// particle.frag using an undeclared identifier on line 21, inside #ifdef SOFT_PARTICLES):
// reported once, at the original file and line (through the #include of the common file),
// naming the permutations it occurs in; the exit code is 1; and an output folder built before
// from the good toy domain is left byte for byte (and timestamp for timestamp) as it was.
//
// Run both in process (run_cli, the library entry point) and as a process (the shadergen
// executable, which adds signal handling and the real exit status).
#include <gtest/gtest.h>

#include <set>
#include <sstream>

#include "shadergen/build.h"
#include "shadergen/cli.h"
#include "test_helpers.h"

namespace {

// The exact grouped diagnostic: 6 of the 12 compilable raw permutations have SOFT_PARTICLES
// (raw 4, 5, 6, 7, 12, 14; 13 and 15 are pruned), and so do optimised 2 and 3.
std::string expected_error() {
  return (sgtest::fixtures_dir() / "glsl_error" / "particle.frag").lexically_normal().string() +
         ":21: error: 'soft_fade_scale' : undeclared identifier (in 6 of 12 raw permutations: those with "
         "SOFT [SOFT_PARTICLES]; 2 of 4 optimised permutations; e.g. raw 4 with SOFT_PARTICLES)";
}

struct CliRun {
  int code;
  std::string out;
  std::string err;
};

CliRun run_in_process(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  int code = shadergen::run_cli(args, out, err);
  return {code, out.str(), err.str()};
}

std::vector<std::string> build_args(const sgtest::fs::path& spec, const sgtest::fs::path& out,
                                    const sgtest::fs::path& cache) {
  return {"build", spec.string(), "--out", out.string(), "--cache-dir", cache.string()};
}

// Nothing but `expected` may exist beside the output: no staging or backup folder left behind.
void expect_only(const sgtest::fs::path& dir, const std::set<std::string>& expected) {
  std::set<std::string> present;
  for (const auto& entry : sgtest::fs::directory_iterator(dir)) present.insert(entry.path().filename().string());
  EXPECT_EQ(present, expected);
}

TEST(GlslError, FixtureIsTheToyDomainWithOneBrokenLine) {
  std::string broken = sgtest::read_file(sgtest::fixtures_dir() / "glsl_error" / "particle.frag");
  std::istringstream lines(broken);
  std::string line;
  for (int n = 1; n <= 21 && std::getline(lines, line); ++n) {
  }
  EXPECT_EQ(line, "    color.a *= clamp((scene - gl_FragCoord.z) * soft_fade_scale, 0.0, 1.0);")
      << "the tests expect the error on line 21";
}

TEST(GlslError, LibraryReportsOneGroupedDiagnostic) {
  sgtest::TempDir dir("glsl-error-lib");
  auto result = sgtest::build(sgtest::glsl_error_spec(), dir / "out", dir / "cache");
  ASSERT_FALSE(result.ok());
  ASSERT_EQ(result.errors().size(), 1u);
  const shadergen::Diagnostic& d = result.errors().front();
  EXPECT_EQ(d.line, 21);
  EXPECT_EQ(d.to_string(), expected_error());
  EXPECT_FALSE(sgtest::fs::exists(dir / "out"));
}

TEST(GlslError, CliKeepsThePreviousOutputIntact) {
  sgtest::TempDir dir("glsl-error-cli");
  const sgtest::fs::path out = dir / "out";
  CliRun good = run_in_process(build_args(sgtest::toy_spec(), out, dir / "cache"));
  ASSERT_EQ(good.code, 0) << good.err;
  auto bytes_before = sgtest::snapshot(out);
  auto times_before = sgtest::mtimes(out);
  ASSERT_FALSE(bytes_before.empty());

  CliRun bad = run_in_process(build_args(sgtest::glsl_error_spec(), out, dir / "cache"));
  EXPECT_EQ(bad.code, 1);
  EXPECT_TRUE(sgtest::contains(bad.err, expected_error() + "\n")) << bad.err;
  EXPECT_EQ(sgtest::count_of(bad.err, "error:"), 1u) << "one grouped error, no follow-on noise:\n" << bad.err;
  EXPECT_TRUE(bad.out.empty()) << bad.out;

  auto bytes_after = sgtest::snapshot(out);
  EXPECT_EQ(bytes_after, bytes_before) << sgtest::describe_difference(bytes_before, bytes_after);
  EXPECT_EQ(sgtest::mtimes(out), times_before);
  expect_only(dir.path(), {"cache", "out"});
}

TEST(GlslError, ExecutableExitsOneAndKeepsThePreviousOutputIntact) {
  sgtest::TempDir dir("glsl-error-exe");
  const sgtest::fs::path out = dir / "out";
  sgtest::ProcessResult good =
      sgtest::run_process(sgtest::shadergen_exe(), build_args(sgtest::toy_spec(), out, dir / "cache"));
  ASSERT_EQ(good.exit_code, 0) << good.err;
  auto bytes_before = sgtest::snapshot(out);
  auto times_before = sgtest::mtimes(out);

  sgtest::ProcessResult bad =
      sgtest::run_process(sgtest::shadergen_exe(), build_args(sgtest::glsl_error_spec(), out, dir / "cache"));
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_TRUE(sgtest::contains(bad.err, expected_error() + "\n")) << bad.err;
  EXPECT_EQ(sgtest::count_of(bad.err, "error:"), 1u) << bad.err;

  auto bytes_after = sgtest::snapshot(out);
  EXPECT_EQ(bytes_after, bytes_before) << sgtest::describe_difference(bytes_before, bytes_after);
  EXPECT_EQ(sgtest::mtimes(out), times_before);
  expect_only(dir.path(), {"cache", "out"});
}

TEST(GlslError, FixingTheErrorBuildsAgain) {
  // A copy of the broken fixture, repaired by declaring the missing constant before main().
  sgtest::TempDir dir("glsl-error-fixed");
  sgtest::fs::path domain = dir / "glsl_error";
  sgtest::fs::create_directories(domain);
  std::string spec = sgtest::read_file(sgtest::glsl_error_spec());
  // The copy lives elsewhere: point its relative paths back at the toy fixture.
  for (const std::string from : {"\"../toy/include\"", "\"../toy/sort.comp\""}) {
    auto at = spec.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    std::string absolute = "\"" + (sgtest::fixtures_dir() / "toy").string() + from.substr(7);
    spec.replace(at, from.size(), absolute);
  }
  sgtest::write_file(domain / "glsl_error.json", spec);
  std::string shader = sgtest::read_file(sgtest::fixtures_dir() / "glsl_error" / "particle.frag");
  const std::string anchor = "void main() {";
  ASSERT_NE(shader.find(anchor), std::string::npos);
  shader.insert(shader.find(anchor), "const float soft_fade_scale = 50.0;\n");
  sgtest::write_file(domain / "particle.frag", shader);

  CliRun fixed = run_in_process(build_args(domain / "glsl_error.json", dir / "out", dir / "cache"));
  EXPECT_EQ(fixed.code, 0) << fixed.err;
  EXPECT_TRUE(sgtest::contains(fixed.out, "16 raw (4 pruned), 4 optimised, 1 companion")) << fixed.out;
}

}  // namespace

namespace {

// A one-feature domain around `shader` (and `include/loop.glsl` when given), built in process;
// the first error, as the CLI prints it.
std::string first_error_of(const sgtest::fs::path& dir, const std::string& shader, const std::string& include = {}) {
  sgtest::write_file(dir / "s.frag", shader);
  if (!include.empty()) sgtest::write_file(dir / "include" / "loop.glsl", include);
  sgtest::write_file(dir / "d.json",
                     R"({"format": 1, "name": "d", "uber_shader": {"path": "s.frag"},
                         "raw": {"features": [{"name": "A", "bit": 0, "define": "HAS_A", "unread": "allowed"}]}})");
  auto built = shadergen::build(sgtest::build_options(dir / "d.json", dir / "out", {}));
  return built.ok() ? std::string("built") : built.errors().front().to_string();
}

// An include that includes itself without a guard used to recurse until memory ran out (the
// glsl fuzzer's regression-include-cycle-*): now an error at the #include, at once.
TEST(GlslError, AnIncludeCycleIsAnErrorNotAHang) {
  sgtest::TempDir dir("glsl-include-cycle");
  std::string error = first_error_of(
      dir.path(),
      "#version 450\n#include \"include/loop.glsl\"\nlayout(location = 0) out vec4 c;\nvoid main() { c = vec4(1); }\n",
      "#include \"loop.glsl\"\n");
  EXPECT_EQ(error, (dir.path() / "include" / "loop.glsl").string() +
                       ":1: error: '#include' : #include nested more than 64 deep: an include cycle? for header name: "
                       "loop.glsl (in 2 of 2 raw permutations: all of them; e.g. raw 0 (no defines))");
}

// The shader's own bytes reach glslang's messages: a control byte is shown escaped.
TEST(GlslError, ControlBytesInAMessageAreEscaped) {
  sgtest::TempDir dir("glsl-escape");
  std::string error = first_error_of(
      dir.path(), "#version 450\nlayout(location = 0) out vec4 c;\nvoid main() { c = vec4(1); \x1b[2J }\n");
  EXPECT_EQ(error, (dir.path() / "s.frag").string() +
                       ":3: error: '\\x1b' : unexpected token (in 2 of 2 raw permutations: all of them; e.g. raw 0 (no "
                       "defines))");
}

// glslang lists the extensions that would help on the lines after the message: they are kept.
TEST(GlslError, TheExtensionsGlslangSuggestsAreKept) {
  sgtest::TempDir dir("glsl-extensions");
  std::string error = first_error_of(dir.path(),
                                     "#version 450\nlayout(location = 0) out vec4 c;\n"
                                     "void main() { c = vec4(1); c.x = float(subgroupElect()); }\n");
  EXPECT_EQ(error.find(":3: error: 'subgroupElect' : required extension not requested: "),
            (dir.path() / "s.frag").string().size())
      << error;
  EXPECT_EQ(error.find(": (in"), std::string::npos) << "no message ends in a bare colon: " << error;
}

}  // namespace
