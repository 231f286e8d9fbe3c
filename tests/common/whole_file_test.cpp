// The project's one file reader (common/whole_file): exact bytes from regular files and from
// files without a size, the limit, and what each failure reports.
#include <gtest/gtest.h>
#include <whole_file/whole_file.h>

#include <cstdint>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

#include <testsupport/scratch_dir.h>

// A namespace of this file's own: the test executables are unity builds (tests/CMakeLists.txt).
namespace whole_file_test {
namespace {
namespace fs = std::filesystem;
using Step = whole_file::Failure::Step;

fs::path scratch() { return testsupport::scratch_dir(COMMON_TEST_SCRATCH); }

void write(const fs::path& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

// Bytes that are not text: every byte value, NULs included, longer than one read chunk.
std::string all_byte_values(std::size_t size) {
  std::string bytes(size, '\0');
  for (std::size_t i = 0; i < size; ++i) bytes[i] = static_cast<char>(i * 7 % 256);
  return bytes;
}

TEST(WholeFile, ReadsEveryByteIntoEitherContainer) {
  const fs::path file = scratch() / "data.bin";
  const std::string expected = all_byte_values(10000);
  write(file, expected);
  std::string text;
  EXPECT_FALSE(whole_file::read(file, text));
  EXPECT_EQ(text, expected);
  std::vector<std::uint8_t> bytes{1, 2, 3};  // replaced, not appended to
  EXPECT_FALSE(whole_file::read(file, bytes));
  EXPECT_EQ(std::string(bytes.begin(), bytes.end()), expected);
}

TEST(WholeFile, ReadsAnEmptyFile) {
  const fs::path file = scratch() / "empty";
  write(file, "");
  std::string text = "old";
  EXPECT_FALSE(whole_file::read(file, text));
  EXPECT_EQ(text, "");
}

// /proc files report size 0 and still have content: the reader must read to the end.
TEST(WholeFile, ReadsAFileWithoutAKnownSize) {
  std::string status;
  ASSERT_FALSE(whole_file::read("/proc/self/status", status));
  EXPECT_NE(status.find("Name:"), std::string::npos);
  EXPECT_NE(status.find("VmRSS:"), std::string::npos);
}

TEST(WholeFile, AMissingFileFailsToOpenNamingThePathAndTheReason) {
  const fs::path missing = scratch() / "missing.txt";
  std::string text = "old";
  const auto failure = whole_file::read(missing, text);
  ASSERT_TRUE(failure);
  EXPECT_EQ(failure->step, Step::open);
  EXPECT_EQ(failure->reason, std::errc::no_such_file_or_directory);
  EXPECT_EQ(whole_file::describe(*failure), missing.string() + ": cannot open: No such file or directory");
  EXPECT_EQ(text, "");
}

TEST(WholeFile, AFolderIsNoFile) {
  const fs::path dir = scratch();
  std::string text;
  const auto failure = whole_file::read(dir, text);
  ASSERT_TRUE(failure);
  EXPECT_EQ(failure->step, Step::read);
  EXPECT_EQ(failure->reason, std::errc::is_a_directory);
  EXPECT_EQ(whole_file::describe(*failure), dir.string() + ": read failed: Is a directory");
}

TEST(WholeFile, AFileOverTheLimitIsRefusedWithItsSize) {
  const fs::path file = scratch() / "big";
  write(file, std::string(101, 'x'));
  std::vector<std::uint8_t> bytes;
  EXPECT_FALSE(whole_file::read(file, bytes, 101));
  EXPECT_EQ(bytes.size(), 101u);
  const auto failure = whole_file::read(file, bytes, 100);
  ASSERT_TRUE(failure);
  EXPECT_EQ(failure->step, Step::too_large);
  EXPECT_EQ(failure->size, 101u);
  EXPECT_EQ(failure->limit, 100u);
  EXPECT_EQ(whole_file::describe(*failure), file.string() + ": 101 bytes, more than the 100 allowed");
  EXPECT_TRUE(bytes.empty());
}

TEST(WholeFile, TheLimitHoldsForAFileWithoutAKnownSize) {
  std::string status;
  const auto failure = whole_file::read("/proc/self/status", status, 10);
  ASSERT_TRUE(failure);
  EXPECT_EQ(failure->step, Step::too_large);
  EXPECT_GT(failure->size, 10u);
  EXPECT_TRUE(status.empty());
}

}  // namespace
}  // namespace whole_file_test
