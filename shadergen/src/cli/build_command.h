// build_command.h - `shadergen build`: its options, and running it with them.
#pragma once

#include <CLI/CLI.hpp>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "cache/remote_defaults.h"

namespace shadergen {

struct BuildArgs {
  std::string spec, out, cache_dir, depfile, cpp_name, ns, target_env;
  std::vector<std::string> defines;
  std::string variants;  // --variants FILE, or empty
  unsigned jobs = 0;
  bool no_cache = false, stats = false, verbose = false, strip_debug = false;
  std::string remote_cache;
  bool remote_cache_readonly = false;
  std::string remote_cache_secret_file;
  // Seconds.
  double remote_cache_budget = std::chrono::duration<double>(kDefaultRemoteCacheBudget).count();
  std::string shard;  // "I/N", or empty
  bool require_remote_hits = false;
  std::uint32_t shards = 0;
};

// Adds the `build` subcommand and its options to `app`; a parse fills `args`.
CLI::App* add_build_command(CLI::App& app, BuildArgs& args);

// Runs a parsed `build`: the summary line (and --stats) on `out`, progress and errors on `err`.
// `interrupted` is polled between jobs (set by SIGINT/SIGTERM). Returns the exit code.
int run_build(const BuildArgs& args, const std::atomic<bool>& interrupted, std::ostream& out, std::ostream& err);

}  // namespace shadergen
