// The bounded-memory build (issue 34, item 2): blob bytes go to a spill folder beside the output
// as they are made, and the generated source is streamed to a file. Checked here: the output
// is the same whatever the path taken (cold, warm, serial), the spill folder is gone after a
// successful, a failed and a cancelled build, and unchanged files are still hard-linked from
// the previous output (same inode, same timestamp) when other files change.
#include <gtest/gtest.h>

#include <set>

#include <sys/stat.h>
#include <unistd.h>

#include "output/output_dir.h"
#include "shadergen/build.h"
#include "test_helpers.h"

// A namespace of this file's own: the test executables are unity builds (tests/CMakeLists.txt).
namespace spill_test {
namespace {

namespace fs = sgtest::fs;

// The toy fixture built into `out` with no cache: every blob is compiled, so every one is spilled.
shadergen::BuildOptions cold_toy_build_into(const fs::path& out) {
  shadergen::BuildOptions options = sgtest::build_options(sgtest::toy_spec(), out, {});
  options.use_cache = false;
  return options;
}

std::string first_error(const shadergen::Result<shadergen::BuildSummary>& r) {
  return r.ok() ? std::string() : r.errors().front().to_string();
}

std::set<std::string> names_in(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.insert(entry.path().filename().string());
  return names;
}

bool spill_folder_beside(const fs::path& out) {
  const std::string prefix = "." + out.filename().string() + ".spill.";
  for (const auto& entry : fs::directory_iterator(out.parent_path()))
    if (entry.path().filename().string().rfind(prefix, 0) == 0) return true;
  return false;
}

ino_t inode_of(const fs::path& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 ? st.st_ino : 0;
}

std::map<std::string, ino_t> inodes(const fs::path& dir) {
  std::map<std::string, ino_t> out;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.is_regular_file()) out[entry.path().lexically_relative(dir).generic_string()] = inode_of(entry.path());
  return out;
}

TEST(Spill, NothingIsLeftBesideTheOutputAfterASuccessfulBuild) {
  sgtest::TempDir dir("spill-success");
  shadergen::BuildOptions options = cold_toy_build_into(dir / "out");
  auto summary = shadergen::build(options);
  ASSERT_TRUE(summary.ok()) << first_error(summary);
  EXPECT_EQ(names_in(dir.path()), (std::set<std::string>{"out"}));
  EXPECT_EQ(sgtest::snapshot(dir / "out").count("toy_particles.cpp"), 1u);
}

TEST(Spill, ColdSerialAndWarmBuildsWriteTheSameBytes) {
  sgtest::TempDir dir("spill-same");
  auto cold = sgtest::build(sgtest::toy_spec(), dir / "cold", dir / "cache");
  ASSERT_TRUE(cold.ok()) << first_error(cold);
  shadergen::BuildOptions serial = sgtest::build_options(sgtest::toy_spec(), dir / "serial", {});
  serial.use_cache = false;
  serial.jobs = 1;
  auto one = shadergen::build(serial);
  ASSERT_TRUE(one.ok()) << first_error(one);
  auto warm = sgtest::build(sgtest::toy_spec(), dir / "warm", dir / "cache");
  ASSERT_TRUE(warm.ok()) << first_error(warm);
  EXPECT_EQ(warm->compiled, 0u);
  auto reference = sgtest::snapshot(dir / "cold");
  auto serial_bytes = sgtest::snapshot(dir / "serial");
  auto warm_bytes = sgtest::snapshot(dir / "warm");
  EXPECT_EQ(serial_bytes, reference) << sgtest::describe_difference(serial_bytes, reference);
  EXPECT_EQ(warm_bytes, reference) << sgtest::describe_difference(warm_bytes, reference);
}

// The commit fails after every blob was spilled: the output path is a file.
TEST(Spill, NothingIsLeftBesideTheOutputAfterAFailedBuild) {
  sgtest::TempDir dir("spill-failure");
  sgtest::write_file(dir / "out", "not a folder");
  shadergen::BuildOptions options = cold_toy_build_into(dir / "out");
  auto summary = shadergen::build(options);
  ASSERT_FALSE(summary.ok());
  EXPECT_TRUE(sgtest::contains(first_error(summary), "not a folder")) << first_error(summary);
  EXPECT_EQ(names_in(dir.path()), (std::set<std::string>{"out"}));
  EXPECT_EQ(sgtest::read_file(dir / "out"), "not a folder");
}

// Cancelled once blobs are on disk (the spill folder exists): the build fails, the previous
// output stays as it was and the spill folder is removed.
TEST(Spill, NothingIsLeftBesideTheOutputAfterACancelledBuild) {
  sgtest::TempDir dir("spill-cancel");
  auto first = sgtest::build(sgtest::toy_spec(), dir / "out", dir / "cache");
  ASSERT_TRUE(first.ok()) << first_error(first);
  auto bytes_before = sgtest::snapshot(dir / "out");
  auto times_before = sgtest::mtimes(dir / "out");
  shadergen::BuildOptions options = cold_toy_build_into(dir / "out");
  options.cpp_namespace = "other_namespace";  // the output would change if it were written
  bool saw_spill = false;
  const fs::path out = dir / "out";
  options.cancelled = [&] { return saw_spill = saw_spill || spill_folder_beside(out); };
  auto summary = shadergen::build(options);
  ASSERT_FALSE(summary.ok());
  EXPECT_TRUE(saw_spill) << "the build was to be cancelled with blobs in the spill folder";
  EXPECT_TRUE(sgtest::contains(first_error(summary), "interrupted")) << first_error(summary);
  EXPECT_EQ(names_in(dir.path()), (std::set<std::string>{"cache", "out"}));
  EXPECT_EQ(sgtest::snapshot(dir / "out"), bytes_before);
  EXPECT_EQ(sgtest::mtimes(dir / "out"), times_before);
}

// A rebuild with nothing changed writes nothing; one that changes one file (stats.json added)
// links every unchanged file, blobs and the streamed source included, from the previous output:
// same inode, same timestamp.
TEST(Spill, UnchangedFilesAreHardLinkedFromThePreviousOutput) {
  sgtest::TempDir dir("spill-links");
  shadergen::BuildOptions options = cold_toy_build_into(dir / "out");
  auto first = shadergen::build(options);
  ASSERT_TRUE(first.ok()) << first_error(first);
  auto times_before = sgtest::mtimes(dir / "out");
  auto inodes_before = inodes(dir / "out");
  auto same = shadergen::build(options);
  ASSERT_TRUE(same.ok()) << first_error(same);
  EXPECT_FALSE(same->output_changed);
  EXPECT_EQ(sgtest::mtimes(dir / "out"), times_before);
  EXPECT_EQ(inodes(dir / "out"), inodes_before);
  EXPECT_EQ(names_in(dir.path()), (std::set<std::string>{"out"}));
  options.write_stats = true;
  auto second = shadergen::build(options);
  ASSERT_TRUE(second.ok()) << first_error(second);
  EXPECT_TRUE(second->output_changed);
  auto times_after = sgtest::mtimes(dir / "out");
  auto inodes_after = inodes(dir / "out");
  ASSERT_EQ(times_after.erase("stats.json"), 1u);
  ASSERT_EQ(inodes_after.erase("stats.json"), 1u);
  EXPECT_EQ(times_after, times_before);
  EXPECT_EQ(inodes_after, inodes_before);
  EXPECT_EQ(names_in(dir.path()), (std::set<std::string>{"out"}));
}

// A spill folder of a killed build (its process is gone) is cleared at the next commit into the
// same output; one of a live process (this one) is not: that build may still be running.
TEST(Spill, ASpillFolderOfAKilledBuildIsClearedAtTheNextCommit) {
  sgtest::TempDir dir("spill-leftover");
  const fs::path dead = dir / ".out.spill.tmp-99999999-0";  // above any pid_max
  const fs::path live = dir / (".out.spill.tmp-" + std::to_string(::getpid()) + "-999999");
  sgtest::write_file(dead / "blob.spv", "words");
  sgtest::write_file(live / "blob.spv", "words");
  shadergen::StagedOutput staged(dir / "out");
  staged.add("a.txt", "a");
  auto changed = staged.commit();
  ASSERT_TRUE(changed.ok());
  EXPECT_FALSE(fs::exists(dead));
  EXPECT_TRUE(fs::exists(live / "blob.spv"));
}

// StagedOutput's file-backed entries: compared by streaming, so the same bytes are "unchanged".
TEST(Spill, FileBackedEntriesCompareByContent) {
  sgtest::TempDir dir("spill-staged");
  sgtest::write_file(dir / "spill" / "a.bin", std::string(200000, 'x'));
  sgtest::write_file(dir / "spill" / "b.bin", std::string(200000, 'x') + "y");
  shadergen::StagedOutput first(dir / "out");
  first.add_file("a.bin", dir / "spill" / "a.bin");
  first.add("small.txt", "small");
  auto changed = first.commit();
  ASSERT_TRUE(changed.ok());
  EXPECT_TRUE(*changed);
  EXPECT_EQ(sgtest::read_file(dir / "out" / "a.bin"), std::string(200000, 'x'));
  shadergen::StagedOutput same(dir / "out");
  same.add_file("a.bin", dir / "spill" / "a.bin");
  same.add("small.txt", "small");
  ASSERT_TRUE(same.unchanged());
  shadergen::StagedOutput other(dir / "out");
  other.add_file("a.bin", dir / "spill" / "b.bin");
  other.add("small.txt", "small");
  EXPECT_FALSE(other.unchanged());
  changed = other.commit();
  ASSERT_TRUE(changed.ok());
  EXPECT_TRUE(*changed);
  EXPECT_EQ(sgtest::read_file(dir / "out" / "a.bin"), std::string(200000, 'x') + "y");
}

}  // namespace
}  // namespace spill_test
