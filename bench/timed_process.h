// timed_process.h - what the shadergen benchmarks share: a command run through the shell and
// timed from start to exit, medians, and an output folder read back for comparison.
#pragma once

#include "tilelight/base/median.h"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace bench {

struct Run {
  bool ok = false;       // exit status 0
  double seconds = 0.0;  // wall time, start to exit
  std::string out;       // stdout and stderr
};

// Runs `args` (quoted for the shell) with stdin from /dev/null and both outputs into `log`.
Run run(const std::vector<std::string>& args, const std::filesystem::path& log);

// The runtime's median (tilelight/base/median.h): one definition for every timing table.
using tilelight::median;

// "1.234 1.198 1.305": every run, in order, for the report.
std::string seconds_list(const std::vector<double>& values);

std::string read_text(const std::filesystem::path& path);

// Every file of a shadergen output folder but stats.json (timings), relative path -> bytes.
std::map<std::string, std::string> output_files(const std::filesystem::path& dir);

}  // namespace bench
