#include "cli/build_command.h"

#include <command_line/command_line.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>

#include "cli/build_stats.h"
#include "cli/print_errors.h"
#include "shadergen/build.h"

namespace shadergen {
namespace {

// The signing secret: the file's bytes (without trailing line breaks), else
// $SHADERGEN_REMOTE_CACHE_SECRET, else none. Never an argument: command lines reach logs and
// `ps`. Messages name the file, never its contents.
std::optional<std::string> remote_cache_secret(const BuildArgs& a, std::ostream& err) {
  if (a.remote_cache_secret_file.empty()) {
    const char* secret = std::getenv("SHADERGEN_REMOTE_CACHE_SECRET");
    return std::string(secret ? secret : "");
  }
  std::ifstream file(a.remote_cache_secret_file, std::ios::binary);
  std::string secret((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  while (!secret.empty() && (secret.back() == '\n' || secret.back() == '\r')) secret.pop_back();
  if (!file.good() && !file.eof()) secret.clear();
  if (secret.empty()) {
    err << "shadergen: error: --remote-cache-secret-file " << a.remote_cache_secret_file
        << ": cannot read a secret from it (missing, unreadable or empty)\n";
    return std::nullopt;
  }
  return secret;
}

// "; remote: 13 fetched, 0 uploaded, 0 failed" inside the summary's parentheses, with a remote cache.
std::string remote_counts(const BuildSummary& s) {
  if (!s.remote) return {};
  return "; remote: " + std::to_string(s.remote->fetched) + " fetched, " + std::to_string(s.remote->uploaded) +
         " uploaded, " + std::to_string(s.remote->failed) + " failed";
}

// A time in seconds as the help text writes it: "10", "2.5".
std::string seconds_number(std::chrono::milliseconds ms) {
  std::string text = std::to_string(ms.count() / 1000);
  if (long long rest = ms.count() % 1000) {
    std::string fraction = std::to_string(1000 + rest).substr(1);  // three digits
    while (fraction.back() == '0') fraction.pop_back();
    text += "." + fraction;
  }
  return text;
}

// Everything but the secret, the log and the cancellation: what the options say.
BuildOptions options_from(const BuildArgs& a) {
  BuildOptions options;
  options.spec_path = a.spec;
  options.out_dir = a.out;
  options.variants = a.variants;
  options.jobs = a.jobs;
  options.use_cache = !a.no_cache;
  options.cache_dir = a.cache_dir;
  options.depfile = a.depfile;
  options.cpp_name = a.cpp_name;
  options.cpp_namespace = a.ns;
  options.defines = a.defines;
  options.target_env = a.target_env;
  options.write_stats = a.stats;
  options.strip_debug = a.strip_debug;
  options.verbose = a.verbose;
  options.remote_cache_url = a.remote_cache;
  options.remote_cache_read_only = a.remote_cache_readonly;
  options.remote_cache_budget = std::chrono::milliseconds(static_cast<long long>(a.remote_cache_budget * 1000.0));
  options.require_remote_hits = a.require_remote_hits;
  options.shards = a.shards;
  return options;
}

// "I/N" with 0 <= I < N <= kMaxShards, or nullopt.
std::optional<Shard> parse_shard(const std::string& text) {
  std::size_t slash = text.find('/');
  if (slash == std::string::npos || slash == 0 || slash + 1 == text.size() || text.size() > 16) return std::nullopt;
  std::uint64_t parts[2] = {0, 0};
  for (int p = 0; p < 2; ++p) {
    std::string_view digits =
        p == 0 ? std::string_view(text).substr(0, slash) : std::string_view(text).substr(slash + 1);
    for (char c : digits) {
      if (c < '0' || c > '9') return std::nullopt;
      parts[p] = parts[p] * 10 + static_cast<std::uint64_t>(c - '0');
    }
  }
  if (parts[1] == 0 || parts[1] > kMaxShards || parts[0] >= parts[1]) return std::nullopt;
  return Shard{static_cast<std::uint32_t>(parts[0]), static_cast<std::uint32_t>(parts[1])};
}

// The command-line mistakes of the sharded build's options (exit 2), or nullopt. Fills
// options.shard from --shard.
std::optional<std::string> usage_problem(const BuildArgs& a, BuildOptions& options) {
  if (!a.shard.empty()) {
    options.shard = parse_shard(a.shard);
    if (!options.shard) return "--shard " + a.shard + ": expected I/N with 0 <= I < N <= " + std::to_string(kMaxShards);
    if (a.remote_cache.empty())
      return std::string(
          "--shard needs --remote-cache (or SHADERGEN_REMOTE_CACHE): a shard's results reach the "
          "merge only through it");
    if (a.remote_cache_readonly) return std::string("--shard cannot use --remote-cache-readonly: a shard uploads");
    if (a.require_remote_hits) return std::string("--shard and --require-remote-hits exclude each other");
  } else if (a.out.empty()) {
    return std::string("--out is required (except with --shard)");
  }
  if (a.require_remote_hits && a.remote_cache.empty())
    return std::string("--require-remote-hits needs --remote-cache (or SHADERGEN_REMOTE_CACHE)");
  if (a.shards != 0 && !a.require_remote_hits) return std::string("--shards only goes with --require-remote-hits");
  return std::nullopt;
}

// "shadergen: shard 2/8: 1234 distinct sources (1200 uploaded, 34 already on the server) in 9.81 s".
void print_shard_summary(const BuildArgs& a, const BuildSummary& s, std::ostream& out) {
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, " in %.2f s\n", s.seconds);
  out << "shadergen: shard " << s.shard_index << "/" << s.shard_count << ": " << s.shard_sources << " of "
      << s.unique_sources << " distinct sources (" << s.shard_uploaded << " uploaded, " << s.shard_on_server
      << " already on the server)" << seconds;
  if (a.stats) out << format_build_stats(s);
}

// " (one blob serves up to 6 pipelines and 3 branch values)", or nothing for a variant-only domain.
std::string kinds_served(const BuildSummary& s) {
  if (s.most_pipelines_per_blob <= 1 && s.most_branch_values_per_blob <= 1) return {};
  std::string text = " (one blob serves up to ";
  if (s.most_pipelines_per_blob > 1) text += std::to_string(s.most_pipelines_per_blob) + " pipelines";
  if (s.most_pipelines_per_blob > 1 && s.most_branch_values_per_blob > 1) text += " and ";
  if (s.most_branch_values_per_blob > 1) text += std::to_string(s.most_branch_values_per_blob) + " branch values";
  return text + ")";
}

// "shadergen: <out>: 128 raw (32 pruned), 32 optimised, ... in 0.83 s", then --stats.
void print_summary(const BuildArgs& a, const BuildSummary& s, std::ostream& out) {
  out << "shadergen: " << a.out << ": " << s.raw << " raw (" << s.pruned << " pruned), " << s.optimised
      << " optimised, " << s.companions << " companion" << (s.companions == 1 ? "" : "s") << " -> " << s.unique_sources
      << " distinct sources (" << s.compiled << " compiled, " << s.cache_hits << " cached" << remote_counts(s) << "), "
      << s.unique_blobs << " SPIR-V blobs" << kinds_served(s) << (s.output_changed ? "" : "; output unchanged");
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, " in %.2f s\n", s.seconds);
  out << seconds;
  if (s.renumbered_raw_ids > 0) {
    std::string features;
    for (const std::string& change : s.kind_changes) features += (features.empty() ? "" : ", ") + change;
    out << "shadergen: " << a.out << ": note: " << s.renumbered_raw_ids
        << " raw IDs map to other optimised IDs than in the previous output"
        << (features.empty() ? std::string() : " (feature kinds changed: " + features + ")")
        << "; anything keyed by optimised ID (a pipeline cache) is stale\n";
  }
  if (a.stats) out << format_build_stats(s);
}

}  // namespace

CLI::App* add_build_command(CLI::App& app, BuildArgs& args) {
  CLI::App* build_cmd = app.add_subcommand("build", "Compile every permutation of a domain into an output folder");
  build_cmd->add_option("spec", args.spec, "Domain spec (JSON)")->required();
  build_cmd->add_option("--out,-o", args.out,
                        "Output folder: manifest.json, spirv/, <name>.h/.cpp (replaced atomically); required "
                        "except with --shard");
  build_cmd->add_option("--variants", args.variants,
                        "Variants file: the raw combinations to build, one per line (replaces the spec's "
                        "\"variants_file\"; needed past 2^20 raw IDs)");
  build_cmd->add_option("-j,--jobs", args.jobs, "Parallel compile jobs (default: one per hardware thread)")
      ->check(CLI::Range(1u, 1024u));
  build_cmd->add_flag("--no-cache", args.no_cache, "Ignore the content cache and compile everything (a cold build)");
  build_cmd->add_option("--cache-dir", args.cache_dir,
                        "Content cache folder (default: $SHADERGEN_CACHE_DIR, else $XDG_CACHE_HOME/shadergen, "
                        "else ~/.cache/shadergen)");
  build_cmd->add_option("--depfile", args.depfile,
                        "Write a Make-style depfile listing the spec and every GLSL file read");
  build_cmd->add_option("--cpp-name", args.cpp_name, "Base name of the generated .h/.cpp (default: the domain name)");
  build_cmd->add_option("--namespace", args.ns, "C++ namespace of the generated code (default: the domain name)");
  build_cmd
      ->add_option("-D,--define", args.defines,
                   "NAME=VALUE (or NAME, meaning 1) for every shader of the domain; repeatable; adds to and "
                   "replaces the spec's \"defines\"")
      ->allow_extra_args(false);
  build_cmd->add_option("--target-env", args.target_env,
                        "vulkan1.0, vulkan1.1, vulkan1.2 or vulkan1.3: the Vulkan (and so SPIR-V) version to compile "
                        "and validate for (default: the spec's \"target_env\", else vulkan1.2)");
  build_cmd->add_flag("--strip-debug", args.strip_debug,
                      "Write blobs without debug instructions (names, sources, lines), as the spec's "
                      "\"strip_debug\": true; the manifest and registry keep the names");
  build_cmd->add_flag("--stats", args.stats, "Also write stats.json: per-stage counts and per-permutation timings");
  build_cmd->add_flag("-v,--verbose", args.verbose, "One progress line per compiled source");
  build_cmd
      ->add_option("--remote-cache", args.remote_cache,
                   "Content cache shared over HTTP, asked after the local one: GET/PUT URL/<key-prefix>/<key>")
      ->envname("SHADERGEN_REMOTE_CACHE");
  build_cmd->add_flag("--remote-cache-readonly", args.remote_cache_readonly,
                      "Only read the remote cache, never upload to it (developer machines)");
  build_cmd->add_option("--remote-cache-secret-file", args.remote_cache_secret_file,
                        "Sign uploads and accept only signed entries, with the secret in this file (default: "
                        "$SHADERGEN_REMOTE_CACHE_SECRET; none: entries are neither signed nor checked)");
  build_cmd
      ->add_option("--remote-cache-budget", args.remote_cache_budget,
                   "Seconds the remote cache's requests may keep a build waiting in all before it is turned off "
                   "for the rest of the build (default " +
                       seconds_number(kDefaultRemoteCacheBudget) + "; each request waits at most " +
                       seconds_number(kDefaultRemoteCacheRequestLimit) + ")")
      ->check(CLI::Range(0.0, 3600.0));
  build_cmd->add_option("--shard", args.shard,
                        "I/N: compile only shard I (0-based) of N of the domain's distinct sources and store them on "
                        "--remote-cache; writes no output folder; exits 1 unless all of them are on the server "
                        "(docs/distributed.md)");
  build_cmd->add_flag("--require-remote-hits", args.require_remote_hits,
                      "The merge of a sharded build: compile nothing, take every source from the caches, and fail "
                      "(writing nothing) if any is missing");
  build_cmd
      ->add_option("--shards", args.shards,
                   "With --require-remote-hits: how many shards filled the cache, so that missing sources are "
                   "counted per shard")
      ->check(CLI::Range(1u, kMaxShards));
  return build_cmd;
}

int run_build(const BuildArgs& a, const std::atomic<bool>& interrupted, std::ostream& out, std::ostream& err) {
  BuildOptions options = options_from(a);
  if (auto usage = usage_problem(a, options)) {
    err << "shadergen: error: " << *usage << '\n';
    return command_line::kExitUsage;
  }
  auto secret = remote_cache_secret(a, err);
  if (!secret) return command_line::kExitError;
  options.remote_cache_secret = std::move(*secret);
  options.log = [&err](const std::string& line) { err << "shadergen: " << line << std::endl; };
  options.cancelled = [&interrupted] { return interrupted.load(); };
  auto summary = build(options);
  if (!summary) {
    if (interrupted.load()) {
      err << "shadergen: interrupted; " << a.out << " was left as it was\n";
      return command_line::kExitInterrupted;
    }
    return print_errors(summary.errors(), err);
  }
  if (summary->sharded)
    print_shard_summary(a, *summary, out);
  else
    print_summary(a, *summary, out);
  return command_line::kExitSuccess;
}

}  // namespace shadergen
