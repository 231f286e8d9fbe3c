// build_command.h - `shadergen build`: its options, and running it with them.
#pragma once

#include <CLI/CLI.hpp>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "shadergen/build_options.h"

namespace shadergen {

// `shadergen build`'s command line: CLI11 binds the options straight into `options`, the
// library's own type. Only what is not a build option stays beside it: the secret's file (read
// after the parse, so that the secret never is an argument) and the three flags whose
// combination makes the role (--shard, --require-remote-hits, --shards).
struct BuildCommandLine {
  BuildOptions options;
  std::string remote_cache_secret_file;
  std::string shard;  // "I/N", or empty
  bool require_remote_hits = false;
  std::uint32_t shards = 0;
};

// Adds the `build` subcommand and its options to `app`; a parse fills `line`.
CLI::App* add_build_command(CLI::App& app, BuildCommandLine& line);

// Runs a parsed `build`: the summary line (and --stats) on `out`, progress and errors on `err`.
// `interrupted` is polled between jobs (set by SIGINT/SIGTERM). Returns the exit code.
int run_build(BuildCommandLine& line, const std::atomic<bool>& interrupted, std::ostream& out, std::ostream& err);

}  // namespace shadergen
