#include "timed_process.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace bench {
namespace {

std::string quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

Run run(const std::vector<std::string>& args, const std::filesystem::path& log) {
  std::string command;
  for (const std::string& arg : args) command += (command.empty() ? "" : " ") + quote(arg);
  command += " >" + quote(log.string()) + " 2>&1 </dev/null";
  auto start = std::chrono::steady_clock::now();
  int status = std::system(command.c_str());
  Run r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.ok = status == 0;
  r.out = read_text(log);
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

std::map<std::string, std::string> output_files(const std::filesystem::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir))
    if (entry.is_regular_file() && entry.path().filename() != "stats.json")
      files[entry.path().lexically_relative(dir).generic_string()] = read_text(entry.path());
  return files;
}

}  // namespace bench
