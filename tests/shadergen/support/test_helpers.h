// The helpers every shadergen test uses: fixture paths, temporary folders, reading and writing
// files, whole-folder snapshots, running the shadergen executable or spirv-val as a process,
// and small text utilities for exact diagnostics.
//
// Every folder a test writes lives under std::filesystem::temp_directory_path() with a name
// unique to the process and the call (TempDir), and every build passes an explicit cache
// folder: no test touches the user's cache or another test's files, whatever ctest -j runs
// beside it. Each test executable compiles test_helpers.cpp with its own SHADERGEN_SOURCE_DIR.
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include <testsupport/child_process.h>
#include "shadergen/build.h"

namespace sgtest {

namespace fs = std::filesystem;

fs::path source_dir();
fs::path fixtures_dir();
fs::path toy_spec();
fs::path glsl_error_spec();
fs::path split_second_spec();

// The shadergen executable of this build (support/shadergen_exe.cpp; executables that run it
// compile that file, with the path as its one compile definition).
fs::path shadergen_exe();

// What a test's build starts from: `spec` built into `out` with the test's own cache folder
// `cache` (never the user's) and two jobs. A test sets whatever else it checks, then calls
// shadergen::build().
shadergen::BuildOptions build_options(const fs::path& spec, const fs::path& out, const fs::path& cache);
// shadergen::build(build_options(spec, out, cache)).
shadergen::Result<shadergen::BuildSummary> build(const fs::path& spec, const fs::path& out, const fs::path& cache);

std::string read_file(const fs::path& path);
// Creates the parent folders; replaces the file.
void write_file(const fs::path& path, const std::string& bytes);

// A fresh, empty folder under the system temporary folder, removed when the object dies.
class TempDir {
 public:
  explicit TempDir(const std::string& tag);
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const fs::path& path() const { return path_; }
  fs::path operator/(const std::string& name) const { return path_ / name; }

 private:
  fs::path path_;
};

// Environment variables changed for one test: the ones named are saved when the object is made
// and put back (set to the saved value, or unset) when it dies, so the next test in the same
// process sees the environment it started with.
class ScopedEnvironment {
 public:
  explicit ScopedEnvironment(std::vector<std::string> names);
  ~ScopedEnvironment();
  ScopedEnvironment(const ScopedEnvironment&) = delete;
  ScopedEnvironment& operator=(const ScopedEnvironment&) = delete;

 private:
  std::vector<std::pair<std::string, std::optional<std::string>>> saved_;
};

// Every regular file under `dir`: relative path -> bytes.
std::map<std::string, std::string> snapshot(const fs::path& dir);
// Every regular file under `dir`: relative path -> modification time.
std::map<std::string, fs::file_time_type> mtimes(const fs::path& dir);
// Lists which files differ between two snapshots, for readable failure messages.
std::string describe_difference(const std::map<std::string, std::string>& a,
                                const std::map<std::string, std::string>& b);

// exit_code, out, err: exit_code is -1 when the process did not exit normally.
using ProcessResult = testsupport::ChildOutcome;

// Runs `program args...` (a bare name is looked up in PATH) with stdout and stderr captured and
// stdin empty, through testsupport::Child.
ProcessResult run_process(const fs::path& program, const std::vector<std::string>& args);

// The external validator, as a second opinion beside shadergen's own validate_spirv().
ProcessResult spirv_val(const fs::path& blob, const std::string& target_env = "vulkan1.2");

// The first diagnostic of parse_domain(text, "spec.json") as printed, or "(no error)".
std::string first_spec_error(const std::string& text);

// `text` with its first `from` replaced by `to`, for table cases that break one thing in a
// valid spec. A `from` the text lacks is a bug in the test: it fails the test.
std::string replace_once(std::string text, const std::string& from, const std::string& to);

// One case of a spec error table: a broken spec and the exact first diagnostic it gives.
struct SpecErrorCase {
  const char* name;
  std::string text;
  std::string expected;
};
// Names the case in test names and messages instead of printing the struct's bytes.
void PrintTo(const SpecErrorCase& c, std::ostream* os);

bool contains(const std::string& text, const std::string& part);
// Non-overlapping occurrences of `part` in `text`.
std::size_t count_of(const std::string& text, const std::string& part);

// 1-based line and column of byte `offset` in `text`, as shadergen's diagnostics count them.
struct Position {
  int line = 1;
  int column = 1;
};
Position position_of(const std::string& text, std::size_t offset);
// "file:line:column" of byte `offset` of `text`.
std::string where(const std::string& file, const std::string& text, std::size_t offset);

}  // namespace sgtest
