// Fuzz entry point: `shadergen` argument handling, through run_cli() in process.
//
// The input is split on NUL and newline into the argument list. It runs inside a scratch
// folder (made once per process under the system temporary folder, removed at exit) that holds
// the specs an argument list can name: copies of the toy and Split/Second specs (valid, so
// `lut`, `list` and `explain` do their whole work) and a broken one.
//
// Sandbox, so that no input compiles GLSL or writes outside the scratch folder:
// - no shader file exists in the scratch folder, so `build` always stops at reading the
//   uber-shader, before it compiles, writes the cache, the output folder or the depfile;
// - every '/' in an argument becomes '_' and ".." becomes "__", so every path an argument
//   names is a plain name inside the scratch folder;
// - SHADERGEN_CACHE_DIR points into the scratch folder, so the default cache is never the
//   user's.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz_check.h"
#include "shadergen/cli.h"

namespace {

namespace fs = std::filesystem;

constexpr std::size_t kMaxArgs = 64;  // longer lists only repeat what shorter ones test

void copy_spec(const fs::path& from, const fs::path& to) {
  std::ifstream in(from, std::ios::binary);
  shadergen::fuzz::require(static_cast<bool>(in), "the fixture specs are readable (SHADERGEN_SOURCE_DIR)");
  std::ofstream(to, std::ios::binary) << in.rdbuf();
}

class Scratch {
 public:
  Scratch() {
    fs::path source = SHADERGEN_SOURCE_DIR;
    std::string pattern = (fs::temp_directory_path() / "shadergen-fuzz-cli-XXXXXX").string();
    shadergen::fuzz::require(mkdtemp(pattern.data()) != nullptr, "a scratch folder can be made");
    dir_ = pattern;
    copy_spec(source / "tests/fixtures/toy/toy.json", dir_ / "toy.json");
    copy_spec(source / "permutations/split_second.json", dir_ / "split_second.json");
    std::ofstream(dir_ / "bad.json") << "{ \"name\": \"bad\", }\n";
    fs::create_directories(dir_ / "folder");
    setenv("SHADERGEN_CACHE_DIR", (dir_ / "cache").c_str(), 1);
    fs::current_path(dir_);
  }
  ~Scratch() {
    std::error_code ignored;
    fs::current_path(dir_.parent_path(), ignored);
    fs::remove_all(dir_, ignored);
  }

 private:
  fs::path dir_;
};

std::string confine(std::string arg) {
  for (char& c : arg)
    if (c == '/') c = '_';
  if (arg.rfind("..", 0) == 0) arg.replace(0, 2, "__");
  return arg;
}

std::vector<std::string> split_arguments(std::string_view text) {
  std::vector<std::string> args;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= text.size() && args.size() < kMaxArgs; ++i) {
    if (i < text.size() && text[i] != '\0' && text[i] != '\n') continue;
    args.push_back(confine(std::string(text.substr(start, i - start))));
    start = i + 1;
  }
  return args;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static Scratch scratch;
  std::vector<std::string> args = split_arguments(std::string_view(reinterpret_cast<const char*>(data), size));
  std::ostringstream out, err;
  int code = shadergen::run_cli(args, out, err);
  using shadergen::fuzz::require;
  require(code == 0 || code == 1 || code == 2, "the exit code is 0, 1 (input error) or 2 (usage)");
  require(code == 0 || !err.str().empty(), "a failure says why on stderr");
  return 0;
}
