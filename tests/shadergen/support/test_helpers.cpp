#include "test_helpers.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "shadergen/domain.h"

namespace sgtest {

fs::path source_dir() { return fs::path(SHADERGEN_SOURCE_DIR); }
fs::path fixtures_dir() { return source_dir() / "tests" / "fixtures"; }
fs::path toy_spec() { return fixtures_dir() / "toy" / "toy.json"; }
fs::path glsl_error_spec() { return fixtures_dir() / "glsl_error" / "glsl_error.json"; }
fs::path split_second_spec() { return source_dir() / "permutations" / "split_second.json"; }

shadergen::BuildOptions build_options(const fs::path& spec, const fs::path& out, const fs::path& cache) {
  shadergen::BuildOptions options;
  options.spec_path = spec;
  options.out_dir = out;
  options.cache_dir = cache;
  options.jobs = 2;
  return options;
}

shadergen::Result<shadergen::BuildSummary> build(const fs::path& spec, const fs::path& out, const fs::path& cache) {
  return shadergen::build(build_options(spec, out, cache));
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void write_file(const fs::path& path, const std::string& bytes) {
  if (path.has_parent_path()) fs::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << bytes;
}

TempDir::TempDir(const std::string& tag) {
  static std::atomic<unsigned> counter{0};
  auto ticks = std::chrono::steady_clock::now().time_since_epoch().count();
  path_ = fs::temp_directory_path() / ("shadergen-test-" + tag + "-" + std::to_string(::getpid()) + "-" +
                                       std::to_string(counter++) + "-" + std::to_string(ticks));
  fs::remove_all(path_);
  fs::create_directories(path_);
}

TempDir::~TempDir() {
  std::error_code ec;
  fs::remove_all(path_, ec);
}

ScopedEnvironment::ScopedEnvironment(std::vector<std::string> names) {
  for (std::string& name : names) {
    const char* value = std::getenv(name.c_str());
    saved_.emplace_back(std::move(name), value ? std::optional<std::string>(value) : std::nullopt);
  }
}

ScopedEnvironment::~ScopedEnvironment() {
  for (const auto& [name, value] : saved_) {
    if (value)
      ::setenv(name.c_str(), value->c_str(), 1);
    else
      ::unsetenv(name.c_str());
  }
}

std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> files;
  if (!fs::exists(dir)) return files;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.is_regular_file()) files[entry.path().lexically_relative(dir).generic_string()] = read_file(entry.path());
  return files;
}

std::map<std::string, fs::file_time_type> mtimes(const fs::path& dir) {
  std::map<std::string, fs::file_time_type> times;
  if (!fs::exists(dir)) return times;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.is_regular_file()) times[entry.path().lexically_relative(dir).generic_string()] = entry.last_write_time();
  return times;
}

std::string describe_difference(const std::map<std::string, std::string>& a,
                                const std::map<std::string, std::string>& b) {
  std::string text;
  for (const auto& [name, bytes] : a) {
    auto other = b.find(name);
    if (other == b.end())
      text += "  only in the first: " + name + "\n";
    else if (other->second != bytes)
      text += "  differs: " + name + "\n";
  }
  for (const auto& [name, bytes] : b)
    if (!a.count(name)) text += "  only in the second: " + name + "\n";
  return text.empty() ? "  (identical)\n" : text;
}

ProcessResult run_process(const fs::path& program, const std::vector<std::string>& args) {
  return testsupport::Child(program, args).wait();
}

ProcessResult spirv_val(const fs::path& blob, const std::string& target_env) {
  const fs::path installed = "/usr/bin/spirv-val";
  return run_process(fs::exists(installed) ? installed : fs::path("spirv-val"),
                     {"--target-env", target_env, blob.string()});
}

std::string first_spec_error(const std::string& text) {
  auto result = shadergen::parse_domain(text, "spec.json");
  if (result.ok()) return "(no error)";
  return result.errors().front().to_string();
}

std::string replace_once(std::string text, const std::string& from, const std::string& to) {
  auto at = text.find(from);
  if (at == std::string::npos) {
    ADD_FAILURE() << "test bug: '" << from << "' is not in the spec";
    return text;
  }
  return text.replace(at, from.size(), to);
}

void PrintTo(const SpecErrorCase& c, std::ostream* os) { *os << c.name; }

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::size_t count_of(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + part.size())) ++n;
  return n;
}

Position position_of(const std::string& text, std::size_t offset) {
  Position p;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++p.line;
      p.column = 1;
    } else {
      ++p.column;
    }
  }
  return p;
}

std::string where(const std::string& file, const std::string& text, std::size_t offset) {
  Position p = position_of(text, offset);
  return file + ":" + std::to_string(p.line) + ":" + std::to_string(p.column);
}

}  // namespace sgtest
