// Builds of the toy fixture against a remote cache, for the remote-cache tests: each build has
// its own local cache and output folder under a test folder, standing in for one machine.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "shadergen/build.h"

namespace sgtest {

struct RemoteBuild {
  std::optional<shadergen::BuildSummary> summary;  // nullopt: the build failed (see `errors`)
  std::string errors;
  std::vector<std::string> warnings;
  std::map<std::string, std::string> output;
  double seconds = 0.0;  // wall time of build()
};

using ProgressHook = std::function<void(const std::string&)>;
using OptionsHook = std::function<void(shadergen::BuildOptions&)>;

// One build of the toy domain into <dir>/<name>.out with the local cache <dir>/<name>.cache, one
// job at a time. `on_progress` sees every progress line (-v), on the compiling thread.
RemoteBuild build_toy(const std::filesystem::path& dir, const std::string& name, const std::string& url,
                      bool read_only = false, const ProgressHook& on_progress = {});
// The same with any other option set by `tweak` (a secret, a budget).
RemoteBuild build_toy_with(const std::filesystem::path& dir, const std::string& name, const std::string& url,
                           const OptionsHook& tweak, const ProgressHook& on_progress = {});

// What every build must produce: the toy domain built here, without any cache.
std::map<std::string, std::string> reference_output(const std::filesystem::path& dir);

// The files under `dir`, sorted.
std::vector<std::filesystem::path> files_under(const std::filesystem::path& dir);

}  // namespace sgtest
