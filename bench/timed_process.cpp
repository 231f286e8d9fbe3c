#include "timed_process.h"

#include <testsupport/child_process.h>
#include <whole_file/whole_file.h>

#include <chrono>
#include <cstdio>
#include <set>

namespace bench {

std::string read_text(const std::filesystem::path& path) {
  std::string text;
  // Unreadable reads as empty: the step that needed the file then fails and says so.
  (void)whole_file::read(path, text);
  return text;
}

Run run(const std::vector<std::string>& args) {
  const auto start = std::chrono::steady_clock::now();
  testsupport::Child child(args.front(), {args.begin() + 1, args.end()});
  const testsupport::ChildOutcome outcome = child.wait();
  Run r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.ok = outcome.exit_code == 0;
  r.out = outcome.out + outcome.err;
  r.cpu_seconds = outcome.cpu_seconds;
  r.peak_rss_kib = outcome.peak_rss_kib;
  if (!child.started()) r.out = "cannot start " + args.front() + " (fork or pipe failed)\n";
  return r;
}

std::string seconds_list(const std::vector<double>& values) {
  std::string out;
  char number[32];
  for (double v : values) {
    std::snprintf(number, sizeof number, "%s%.3f", out.empty() ? "" : " ", v);
    out += number;
  }
  return out;
}

namespace {

// The relative paths output_files() would give, without the bytes.
std::set<std::string> output_paths(const std::filesystem::path& dir) {
  std::set<std::string> paths;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir))
    if (entry.is_regular_file() && entry.path().filename() != "stats.json")
      paths.insert(entry.path().lexically_relative(dir).generic_string());
  return paths;
}

}  // namespace

std::map<std::string, std::string> output_files(const std::filesystem::path& dir) {
  std::map<std::string, std::string> files;
  for (const std::string& relative : output_paths(dir)) files[relative] = read_text(dir / relative);
  return files;
}

bool same_output_files(const std::filesystem::path& a, const std::filesystem::path& b) {
  const std::set<std::string> paths = output_paths(a);
  if (paths != output_paths(b)) return false;
  for (const std::string& relative : paths)
    if (read_text(a / relative) != read_text(b / relative)) return false;
  return true;
}

}  // namespace bench
