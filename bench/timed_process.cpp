#include "timed_process.h"

#include <testsupport/child_process.h>
#include <whole_file/whole_file.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <set>
#include <vector>

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

namespace {

// Compares two files a block at a time: a 20-feature domain's generated .cpp is about 8 GB, and
// reading both whole is what got the bench killed for memory (twice).
bool same_bytes(const std::filesystem::path& a, const std::filesystem::path& b) {
  std::error_code ec_a, ec_b;
  if (std::filesystem::file_size(a, ec_a) != std::filesystem::file_size(b, ec_b) || ec_a || ec_b) return false;
  std::ifstream in_a(a, std::ios::binary), in_b(b, std::ios::binary);
  if (!in_a || !in_b) return false;
  std::vector<char> block_a(1 << 20), block_b(1 << 20);
  while (in_a && in_b) {
    in_a.read(block_a.data(), static_cast<std::streamsize>(block_a.size()));
    in_b.read(block_b.data(), static_cast<std::streamsize>(block_b.size()));
    if (in_a.gcount() != in_b.gcount() ||
        !std::equal(block_a.begin(), block_a.begin() + in_a.gcount(), block_b.begin()))
      return false;
  }
  return in_a.eof() && in_b.eof();
}

}  // namespace

bool same_output_files(const std::filesystem::path& a, const std::filesystem::path& b) {
  const std::set<std::string> paths = output_paths(a);
  if (paths != output_paths(b)) return false;
  for (const std::string& relative : paths)
    if (!same_bytes(a / relative, b / relative)) return false;
  return true;
}

}  // namespace bench
