#include "remote_builds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>

#include "test_helpers.h"

namespace sgtest {

using shadergen::BuildOptions;

RemoteBuild build_toy_with(const fs::path& dir, const std::string& name, const std::string& url,
                           const OptionsHook& tweak, const ProgressHook& on_progress) {
  BuildOptions options = build_options(toy_spec(), dir / (name + ".out"), dir / (name + ".cache"));
  options.jobs = 1;
  options.verbose = true;
  options.remote_cache_url = url;
  RemoteBuild result;
  options.log = [&](const std::string& line) {
    if (line.rfind("warning: ", 0) == 0)
      result.warnings.push_back(line);
    else if (on_progress)
      on_progress(line);
  };
  if (tweak) tweak(options);
  auto start = std::chrono::steady_clock::now();
  auto summary = shadergen::build(options);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (summary)
    result.summary = *summary;
  else
    result.errors = summary.errors().front().to_string();
  result.output = snapshot(options.out_dir);
  return result;
}

RemoteBuild build_toy(const fs::path& dir, const std::string& name, const std::string& url, bool read_only,
                      const ProgressHook& on_progress) {
  return build_toy_with(
      dir, name, url, [&](BuildOptions& options) { options.remote_cache_read_only = read_only; }, on_progress);
}

std::map<std::string, std::string> reference_output(const fs::path& dir) {
  BuildOptions options = build_options(toy_spec(), dir / "reference.out", {});
  options.use_cache = false;
  EXPECT_TRUE(shadergen::build(options).ok());
  return snapshot(options.out_dir);
}

std::vector<fs::path> files_under(const fs::path& dir) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.is_regular_file()) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace sgtest
