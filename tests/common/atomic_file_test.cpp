// The project's one atomic write (common/atomic_file): what a reader sees, what is left behind
// after each kind of failure, and how failures are described.
#include <atomic_file/atomic_file.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <testsupport/scratch_dir.h>

namespace {
namespace fs = std::filesystem;

std::string read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

fs::path scratch() { return testsupport::scratch_dir(COMMON_TEST_SCRATCH); }

TEST(AtomicFile, WritesANewFileAndReplacesAnOldOneLeavingNoTemporary) {
  const fs::path dir = scratch();
  ASSERT_FALSE(atomic_file::write(dir / "a.bin", std::string("first\0bytes", 11)));
  EXPECT_EQ(read(dir / "a.bin"), std::string("first\0bytes", 11));
  ASSERT_FALSE(atomic_file::write(dir / "a.bin", "second"));
  EXPECT_EQ(read(dir / "a.bin"), "second");
  ASSERT_FALSE(atomic_file::write(dir / "empty", ""));
  EXPECT_EQ(fs::file_size(dir / "empty"), 0u);
  EXPECT_EQ(names_in(dir), (std::vector<std::string>{"a.bin", "empty"}));
}

TEST(AtomicFile, AStagedFileAppearsOnlyAtCommitAndVanishesIfNeverCommitted) {
  const fs::path dir = scratch();
  {
    atomic_file::StagedFile staged(dir / "report.json", "{}");
    ASSERT_FALSE(staged.failure());
    EXPECT_EQ(staged.temporary_path().parent_path(), dir);
    EXPECT_EQ(staged.temporary_path().filename().string().rfind(".report.json.tmp-", 0), 0u);
    EXPECT_EQ(names_in(dir), std::vector<std::string>{staged.temporary_path().filename().string()});
  }
  EXPECT_TRUE(names_in(dir).empty()) << "the destructor removes an uncommitted temporary";
  atomic_file::StagedFile staged(dir / "report.json", "{}");
  atomic_file::StagedFile moved(std::move(staged));
  ASSERT_FALSE(moved.commit());
  EXPECT_EQ(read(dir / "report.json"), "{}");
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"report.json"});
}

TEST(AtomicFile, AMissingFolderIsACreateFailureOnTheTemporary) {
  const fs::path dir = scratch();
  atomic_file::StagedFile staged(dir / "missing" / "out.png", "x");
  ASSERT_TRUE(staged.failure());
  EXPECT_EQ(staged.failure()->step, atomic_file::Failure::Step::create);
  EXPECT_EQ(staged.failure()->path.parent_path(), dir / "missing");
  EXPECT_EQ(atomic_file::describe(*staged.failure()),
            "cannot create " + staged.failure()->path.string() + ": No such file or directory");
  EXPECT_TRUE(staged.temporary_path().empty());
}

TEST(AtomicFile, AFolderInTheWayIsAReplaceFailureAndKeepsTheFolder) {
  const fs::path dir = scratch();
  fs::create_directories(dir / "taken" / "inside");
  const std::optional<atomic_file::Failure> failure = atomic_file::write(dir / "taken", "bytes");
  ASSERT_TRUE(failure);
  EXPECT_EQ(failure->step, atomic_file::Failure::Step::replace);
  EXPECT_EQ(failure->path, dir / "taken");
  EXPECT_EQ(atomic_file::describe(*failure).rfind("cannot replace " + (dir / "taken").string() + ": ", 0), 0u)
      << atomic_file::describe(*failure);
  EXPECT_TRUE(fs::is_directory(dir / "taken" / "inside"));
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"taken"}) << "no temporary left beside it";
}

TEST(AtomicFile, TemporaryNamesAreUniquePerCall) {
  std::set<std::string> names;
  for (int i = 0; i < 100; ++i) names.insert(atomic_file::temporary_name("out"));
  EXPECT_EQ(names.size(), 100u);
  EXPECT_EQ(names.begin()->rfind(".out.tmp-" + std::to_string(::getpid()) + "-", 0), 0u) << *names.begin();
}

}  // namespace
