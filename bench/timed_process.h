// timed_process.h - what the shadergen benchmarks share: a program run (through the project's
// one runner, <testsupport/child_process.h>) and timed from start to exit, and an output folder
// read back for comparison.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace bench {

struct Run {
  bool ok = false;           // exit status 0
  double seconds = 0.0;      // wall time, start to exit
  std::string out;           // stdout, then stderr
  double cpu_seconds = 0.0;  // user + system of the program itself
  long peak_rss_kib = 0;     // its peak resident set
};

// Runs the program args[0] (a path, or a name looked up in PATH) with the other arguments and
// stdin from /dev/null. Precondition: `args` is not empty.
Run run(const std::vector<std::string>& args);

// "1.234 1.198 1.305": every run, in order, for the report.
std::string seconds_list(const std::vector<double>& values);

// The whole file (<whole_file/whole_file.h>); empty when it cannot be read.
std::string read_text(const std::filesystem::path& path);

// Every file of a shadergen output folder but stats.json (timings), relative path -> bytes.
std::map<std::string, std::string> output_files(const std::filesystem::path& dir);

// output_files(a) == output_files(b), one pair of files in memory at a time: the folders of
// the scale bench's largest domains hold more bytes than the machine has memory.
bool same_output_files(const std::filesystem::path& a, const std::filesystem::path& b);

}  // namespace bench
