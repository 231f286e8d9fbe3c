// shadergen under faults, as users meet them: the real executable, run as child processes, raced
// against itself, interrupted with SIGINT/SIGTERM, starved of file size and write permission,
// and fed a damaged cache. The property every test checks: the output folder is either the
// previous one, byte for byte, or the complete new one; nothing temporary is left beside it or
// in the cache; and a failure says what happened and where.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <algorithm>
#include <csignal>
#include <optional>

#include <testsupport/child_process.h>
#include "cache/cache.h"
#include "cache/input_cache.h"
#include "test_helpers.h"

namespace {

namespace fs = std::filesystem;
using testsupport::Child;
using testsupport::ChildOutcome;
using testsupport::ChildSetup;

ChildOutcome run_shadergen(const std::vector<std::string>& args, ChildSetup setup = {}) {
  Child child(sgtest::shadergen_exe(), args, setup);
  return child.wait();
}

// `shadergen build SPEC --out OUT` with the cache in `cache`, or --no-cache when it is empty.
std::vector<std::string> build_args(const fs::path& spec, const fs::path& out, const fs::path& cache,
                                    const std::vector<std::string>& extra = {}) {
  std::vector<std::string> args = {"build", spec.string(), "--out", out.string()};
  if (cache.empty())
    args.push_back("--no-cache");
  else
    args.insert(args.end(), {"--cache-dir", cache.string()});
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

// The names in `dir` (not recursive), sorted: what a user sees beside the output.
std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// Every file under the cache folder that is not a complete, verified entry at its own name:
// temporaries and half-written or damaged entries.
std::vector<std::string> bad_cache_files(const fs::path& cache) {
  std::vector<std::string> bad;
  if (!fs::exists(cache)) return bad;
  for (const auto& entry : fs::recursive_directory_iterator(cache)) {
    if (!entry.is_regular_file()) continue;
    const std::string name = entry.path().filename().string();
    const std::string folder = entry.path().parent_path().filename().string();
    const std::string bytes = sgtest::read_file(entry.path());
    const bool good = name.size() == 64 &&
                      (folder == "inputs" ? shadergen::decode_input_set(name, bytes).has_value()
                                          : folder == name.substr(0, 2) && shadergen::decode_cache_entry(name, bytes));
    if (!good) bad.push_back(entry.path().lexically_relative(cache).string());
  }
  return bad;
}

// The error lines of a run's stderr (progress and warning lines left out).
std::vector<std::string> error_lines(const std::string& err) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < err.size()) {
    std::size_t end = err.find('\n', start);
    if (end == std::string::npos) end = err.size();
    std::string line = err.substr(start, end - start);
    if (sgtest::contains(line, ": error: ") && !sgtest::contains(line, ": warning: ")) lines.push_back(line);
    start = end + 1;
  }
  return lines;
}

bool ends_with(const std::string& text, const std::string& tail) {
  return text.size() >= tail.size() && text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

// An earlier build of the toy domain in `out` whose generated C++ differs from a default build
// (another namespace), so the next default build must replace the folder.
void build_previous_output(const fs::path& out) {
  ChildOutcome r = run_shadergen(build_args(sgtest::toy_spec(), out, {}, {"--namespace", "previous"}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
}

std::map<std::string, std::string> cold_toy_build(const fs::path& out) {
  ChildOutcome r = run_shadergen(build_args(sgtest::toy_spec(), out, {}));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return sgtest::snapshot(out);
}

// --- 1. Two builds into one output, sharing one cache --------------------------------------

// Both processes are started before either is waited for, so their compile phases and their
// commits overlap. Fresh caches make both write the same entries at once; a previous output
// makes both want to replace the folder. The four rounds cover the four combinations of those.
TEST(ConcurrentBuilds, TwoBuildsIntoOneOutputBothSucceedAndTheOutputIsASingleBuilds) {
  sgtest::TempDir dir("race");
  const auto expected = cold_toy_build(dir / "reference");
  ASSERT_FALSE(expected.empty());
  for (int round = 0; round < 4; ++round) {
    SCOPED_TRACE("round " + std::to_string(round));
    const fs::path parent = dir / ("round" + std::to_string(round));
    const fs::path out = parent / "toy";
    const fs::path cache = round % 2 == 0 ? dir / ("cache" + std::to_string(round)) : dir / "shared-cache";
    fs::create_directories(parent);
    if (round % 3 != 0) build_previous_output(out);

    Child first(sgtest::shadergen_exe(), build_args(sgtest::toy_spec(), out, cache, {"-j", "2"}));
    Child second(sgtest::shadergen_exe(), build_args(sgtest::toy_spec(), out, cache, {"-j", "2"}));
    ChildOutcome a = first.wait();
    ChildOutcome b = second.wait();

    ASSERT_EQ(a.exit_code, 0) << a.err;
    ASSERT_EQ(b.exit_code, 0) << b.err;
    const auto got = sgtest::snapshot(out);
    EXPECT_EQ(got, expected) << sgtest::describe_difference(got, expected);
    EXPECT_EQ(names_in(parent), std::vector<std::string>{"toy"}) << "nothing temporary beside the output";
    EXPECT_EQ(bad_cache_files(cache), std::vector<std::string>{});
    // The lock makes the commits take turns: the second finds the first's folder in place.
    const bool a_unchanged = sgtest::contains(a.out, "; output unchanged");
    const bool b_unchanged = sgtest::contains(b.out, "; output unchanged");
    EXPECT_NE(a_unchanged, b_unchanged) << "exactly one build writes the folder:\n" << a.out << b.out;
  }
}

// --- 2. SIGINT / SIGTERM in the middle of a build ------------------------------------------

struct Interrupt {
  const char* name;
  int signal_number;
  bool use_cache;
};

void PrintTo(const Interrupt& i, std::ostream* os) { *os << i.name; }

class InterruptedBuild : public ::testing::TestWithParam<Interrupt> {};

// The real spec compiles ~130 distinct sources (seconds, cold). The signal goes out once the
// first source has been compiled, so the build is certainly running and far from done. If a
// very fast machine still finishes first (exit 0), the attempt proves nothing and is repeated.
TEST_P(InterruptedBuild, LeavesThePreviousOutputAndNoTemporaries) {
  const Interrupt param = GetParam();
  sgtest::TempDir dir("interrupt");
  const fs::path parent = dir / "gen";
  const fs::path out = parent / "split_second";
  for (int attempt = 0; attempt < 3; ++attempt) {
    SCOPED_TRACE("attempt " + std::to_string(attempt));
    fs::remove_all(out);
    build_previous_output(out);
    const auto before = sgtest::snapshot(out);
    const fs::path cache = param.use_cache ? dir / ("cache" + std::to_string(attempt)) : fs::path();

    Child child(sgtest::shadergen_exe(), build_args(sgtest::split_second_spec(), out, cache, {"-v", "-j", "2"}));
    ASSERT_TRUE(child.started());
    const bool compiling = child.wait_for_stderr("] compiled ");
    child.send(param.signal_number);
    ChildOutcome r = child.wait();
    if (r.exit_code == 0) continue;  // finished before the signal arrived

    ASSERT_TRUE(compiling) << r.err;
    EXPECT_EQ(r.exit_code, 130) << r.err;
    EXPECT_TRUE(ends_with(r.err, "shadergen: interrupted; " + out.string() + " was left as it was\n")) << r.err;
    const auto after = sgtest::snapshot(out);
    EXPECT_EQ(after, before) << sgtest::describe_difference(after, before);
    EXPECT_EQ(names_in(parent), std::vector<std::string>{"split_second"});
    if (param.use_cache) {
      EXPECT_EQ(bad_cache_files(cache), std::vector<std::string>{});
      EXPECT_FALSE(sgtest::snapshot(cache).empty()) << "the entries finished before the signal are kept";
    }
    return;
  }
  FAIL() << "three builds finished before the signal reached them; the test needs a bigger spec";
}

INSTANTIATE_TEST_SUITE_P(Signals, InterruptedBuild,
                         ::testing::Values(Interrupt{"sigint_with_cache", SIGINT, true},
                                           Interrupt{"sigterm_with_cache", SIGTERM, true},
                                           Interrupt{"sigint_no_cache", SIGINT, false}),
                         [](const ::testing::TestParamInfo<Interrupt>& param_info) {
                           return std::string(param_info.param.name);
                         });

// A build killed outright (SIGKILL, power loss) between the two renames of the swap leaves the
// previous output set aside and a staging folder; the next build puts the former back and
// removes the latter. Simulated here by arranging the folders as such a kill leaves them.
TEST(KilledBuild, TheNextBuildRestoresTheSetAsideOutputAndRemovesTheStagingFolder) {
  sgtest::TempDir dir("killed");
  const fs::path parent = dir / "gen";
  const fs::path out = parent / "toy";
  ASSERT_EQ(run_shadergen(build_args(sgtest::toy_spec(), out, {})).exit_code, 0);
  const auto before = sgtest::snapshot(out);
  fs::rename(out, parent / ".toy.old.tmp-999999-0");
  sgtest::write_file(parent / ".toy.staging.tmp-999999-1" / "manifest.json", "{\"half\":");

  ChildOutcome r = run_shadergen(build_args(sgtest::toy_spec(), out, {}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(sgtest::contains(r.out, "; output unchanged")) << "the restored folder is already right:\n" << r.out;
  EXPECT_EQ(sgtest::snapshot(out), before);
  EXPECT_EQ(names_in(parent), std::vector<std::string>{"toy"});
}

// --- 3. Writes that fail ------------------------------------------------------------------

// A disk that fills up: RLIMIT_FSIZE in the child (SIGXFSZ ignored, so write() fails with EFBIG,
// as on a full disk it fails with ENOSPC). Small files still fit; the first larger file that
// must be written fails, and the error names it by its place in the output folder.
TEST(FailedWrite, FileSizeLimitGivesAnErrorNamingTheFileAndKeepsThePreviousOutput) {
  constexpr rlim_t kLimit = 4096;
  sgtest::TempDir dir("fsize");
  const fs::path parent = dir / "gen";
  const fs::path out = parent / "toy";
  const fs::path cache = dir / "cache";
  const auto fresh = cold_toy_build(dir / "reference");
  build_previous_output(out);
  const auto before = sgtest::snapshot(out);
  // Every output that grows with the domain is written to the build's spill folder before it is
  // staged, changed or not; the first over the limit fails, named by its place in the output.
  std::vector<std::string> messages;
  for (const auto& [name, bytes] : fresh)
    if (bytes.size() > kLimit) messages.push_back((out / name).string() + ": error: write failed: File too large");
  ASSERT_FALSE(messages.empty()) << "test bug: no output file is larger than " << kLimit << " bytes";

  ChildSetup setup;
  setup.file_size_limit = kLimit;
  for (const fs::path& cache_dir : {fs::path(), cache}) {
    SCOPED_TRACE(cache_dir.empty() ? "--no-cache" : "with a cache");
    ChildOutcome r = run_shadergen(build_args(sgtest::toy_spec(), out, cache_dir), setup);
    EXPECT_EQ(r.exit_code, 1) << r.err;
    const std::vector<std::string> errors = error_lines(r.err);
    ASSERT_EQ(errors.size(), 1u) << r.err;
    EXPECT_NE(std::find(messages.begin(), messages.end(), errors[0]), messages.end()) << r.err;
    const auto after = sgtest::snapshot(out);
    EXPECT_EQ(after, before) << sgtest::describe_difference(after, before);
    EXPECT_EQ(names_in(parent), std::vector<std::string>{"toy"});
    EXPECT_EQ(bad_cache_files(cache), std::vector<std::string>{}) << "failed cache writes leave nothing behind";
  }
}

// Whether uid 65534 can run the executable and read the fixture (needed to test permissions
// when the tests run as root, for whom chmod stops nothing).
bool nobody_can_build() {
  ChildSetup setup;
  setup.drop_to_nobody = true;
  return run_shadergen({"list", sgtest::toy_spec().string()}, setup).exit_code == 0;
}

// The child setup under which mode bits stop a build: as it is, or as uid 65534 when the tests
// run as root (root ignores them). nullopt when uid 65534 cannot run shadergen or read the
// fixture; the caller skips with kCannotDropPrivileges.
std::optional<ChildSetup> setup_that_mode_bits_bind() {
  ChildSetup setup;
  if (::geteuid() != 0) return setup;
  if (!nobody_can_build()) return std::nullopt;
  setup.drop_to_nobody = true;
  return setup;
}

constexpr const char* kCannotDropPrivileges =
    "running as root and uid 65534 cannot run shadergen or read the fixture, so a read-only folder cannot be tested";

TEST(FailedWrite, ReadOnlyParentFolderGivesAnErrorNamingTheOutputAndKeepsIt) {
  sgtest::TempDir dir("readonly");
  const fs::path parent = dir / "gen";
  const fs::path out = parent / "toy";
  build_previous_output(out);
  const auto before = sgtest::snapshot(out);
  const std::optional<ChildSetup> setup = setup_that_mode_bits_bind();
  if (!setup) GTEST_SKIP() << kCannotDropPrivileges;
  fs::permissions(parent, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                              fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec);
  ChildOutcome r = run_shadergen(build_args(sgtest::toy_spec(), out, {}), *setup);
  fs::permissions(parent, fs::perms::owner_all, fs::perm_options::add);

  EXPECT_EQ(r.exit_code, 1) << r.err;
  const std::vector<std::string> errors = error_lines(r.err);
  ASSERT_EQ(errors.size(), 1u) << r.err;
  // The first folder a build makes beside its output is the spill for its outputs' files.
  const std::string start =
      out.string() + ": error: cannot create a spill folder beside it (" + (parent / ".toy.spill.tmp-").string();
  EXPECT_EQ(errors[0].rfind(start, 0), 0u) << r.err;
  EXPECT_TRUE(ends_with(errors[0], "): Permission denied")) << r.err;
  EXPECT_EQ(sgtest::snapshot(out), before);
  EXPECT_EQ(names_in(parent), std::vector<std::string>{"toy"});
}

// Every folder and file under `root` (itself included) loses its write bits, as after a user's
// `chmod -R a-w`.
void make_tree_read_only(const fs::path& root) {
  constexpr fs::perms kWrite = fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write;
  for (const auto& entry : fs::recursive_directory_iterator(root))
    fs::permissions(entry.path(), kWrite, fs::perm_options::remove);
  fs::permissions(root, kWrite, fs::perm_options::remove);
}

// A read-only output folder (its parent writable) is replaced like any other: the previous
// output is set aside and removed whole, leaving nothing hidden beside the new one, and a
// read-only set-aside folder left by an earlier run is removed too. Every build runs as uid
// 65534 under root, which owns the files it must remove.
TEST(FailedWrite, ReadOnlyOutputFolderIsReplacedAndNothingIsLeftBesideIt) {
  sgtest::TempDir dir("readonly-out");
  const fs::path parent = dir / "gen";
  const fs::path out = parent / "toy";
  fs::create_directories(parent);
  const std::optional<ChildSetup> found = setup_that_mode_bits_bind();
  if (!found) GTEST_SKIP() << kCannotDropPrivileges;
  const ChildSetup setup = *found;
  if (setup.drop_to_nobody) {
    ASSERT_EQ(::chown(parent.c_str(), 65534, 65534), 0);
  }
  ASSERT_EQ(run_shadergen(build_args(sgtest::toy_spec(), out, {}, {"--namespace", "previous"}), setup).exit_code, 0);
  make_tree_read_only(out);
  // A leftover of an earlier run that failed to remove what it set aside: a read-only
  // set-aside folder beside a complete output.
  const fs::path leftover = parent / ".toy.old.tmp-999999-0";
  ASSERT_EQ(run_shadergen(build_args(sgtest::toy_spec(), leftover, {}, {"--namespace", "older"}), setup).exit_code, 0);
  make_tree_read_only(leftover);
  ASSERT_EQ(names_in(parent), (std::vector<std::string>{".toy.old.tmp-999999-0", "toy"}));

  ChildOutcome r = run_shadergen(build_args(sgtest::toy_spec(), out, {}), setup);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(sgtest::snapshot(out), cold_toy_build(dir / "reference"));
  EXPECT_EQ(names_in(parent), std::vector<std::string>{"toy"});

  make_tree_read_only(out);  // and again, now that the output is the current one
  r = run_shadergen(build_args(sgtest::toy_spec(), out, {}, {"--namespace", "next"}), setup);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(names_in(parent), std::vector<std::string>{"toy"});
}

// Works as root too: no permission bit involved.
TEST(FailedWrite, OutputUnderARegularFileIsAnErrorNamingBoth) {
  sgtest::TempDir dir("notdir");
  const fs::path blocker = dir / "blocker";
  sgtest::write_file(blocker, "a file where a folder should be");
  const fs::path out = blocker / "toy";
  ChildOutcome r = run_shadergen(build_args(sgtest::toy_spec(), out, {}));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(error_lines(r.err), std::vector<std::string>{out.string() + ": error: cannot create its parent folder " +
                                                         blocker.string() + ": Not a directory"})
      << r.err;
  EXPECT_EQ(sgtest::read_file(blocker), "a file where a folder should be");
  EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"blocker"});
}

// --- 4. A damaged cache -------------------------------------------------------------------

TEST(DamagedCache, RebuildOverItIsByteIdenticalToAColdBuildAndRepairsIt) {
  sgtest::TempDir dir("damaged");
  const fs::path cache = dir / "cache";
  const auto cold = cold_toy_build(dir / "cold");
  ASSERT_EQ(run_shadergen(build_args(sgtest::toy_spec(), dir / "first", cache)).exit_code, 0);
  std::vector<fs::path> entries;
  for (const auto& e : fs::recursive_directory_iterator(cache))  // the blobs; not the input sets
    if (e.is_regular_file() && e.path().parent_path().filename() != "inputs") entries.push_back(e.path());
  std::sort(entries.begin(), entries.end());
  ASSERT_EQ(entries.size(), 13u);

  const std::string whole = sgtest::read_file(entries[0]);
  sgtest::write_file(entries[0], whole.substr(0, whole.size() / 2));  // truncated
  std::string flipped = sgtest::read_file(entries[1]);
  flipped[flipped.size() / 2] = static_cast<char>(flipped[flipped.size() / 2] ^ 0x10);
  sgtest::write_file(entries[1], flipped);  // one bit of the payload changed
  const shadergen::CachedBlob foreign{{0x07230203u, 0x00010500u, 0u, 1u, 0u}, false, {}};
  sgtest::write_file(entries[2], shadergen::encode_cache_entry(std::string(64, 'f'), foreign));  // another key
  sgtest::write_file(entries[3], "");                                                            // empty
  sgtest::write_file(entries[4], sgtest::read_file(entries[5]));  // a valid entry of another source

  ChildOutcome r = run_shadergen(build_args(sgtest::toy_spec(), dir / "warm", cache));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(sgtest::contains(r.out, "(5 compiled, 8 cached)")) << r.out;
  const auto warm = sgtest::snapshot(dir / "warm");
  EXPECT_EQ(warm, cold) << sgtest::describe_difference(warm, cold);
  EXPECT_EQ(bad_cache_files(cache), std::vector<std::string>{}) << "the damaged entries were rewritten";
}

}  // namespace
