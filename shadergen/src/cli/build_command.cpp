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
std::optional<std::string> remote_cache_secret(const BuildCommandLine& a, std::ostream& err) {
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

// A mistake on the command line: its message, exit 2.
int print_usage_error(const Diagnostic& error, std::ostream& err) {
  err << "shadergen: error: " << error.message << '\n';
  return command_line::kExitUsage;
}

// The role from its three flags. The role's factories check each value; the combinations of
// flags are the command line's own rules.
Result<BuildRole> role_of(const BuildCommandLine& line) {
  if (!line.shard.empty()) {
    if (line.require_remote_hits) return make_error("--shard and --require-remote-hits exclude each other");
    if (line.shards != 0) return make_error("--shards only goes with --require-remote-hits");
    return BuildRole::shard(line.shard);
  }
  if (line.require_remote_hits) return BuildRole::merge(line.shards);
  if (line.shards != 0) return make_error("--shards only goes with --require-remote-hits");
  return BuildRole();
}

// "shadergen: shard 2/8: 1234 of 9872 compile jobs, 1234 distinct sources (1200 uploaded, 34
// already on the server) in 9.81 s"; uploads that replaced a copy on the server that failed the
// checks are counted among them.
void print_shard_summary(const BuildOptions& a, const BuildSummary& s, std::ostream& out) {
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, " in %.2f s\n", s.seconds);
  out << "shadergen: shard " << s.shard_index << "/" << s.shard_count << ": " << s.permutations << " of "
      << s.domain_permutations << " compile jobs, " << s.shard_sources << " distinct sources (" << s.shard_uploaded
      << " uploaded"
      << (s.shard_replaced ? ", of which " + std::to_string(s.shard_replaced) + " replaced a corrupt copy" : "") << ", "
      << s.shard_on_server << " already on the server)" << seconds;
  if (a.write_stats) out << format_build_stats(s);
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
void print_summary(const BuildOptions& a, const BuildSummary& s, std::ostream& out) {
  out << "shadergen: " << a.out_dir.string() << ": " << s.raw << " raw (" << s.pruned << " pruned), " << s.optimised
      << " optimised, " << s.companions << " companion" << (s.companions == 1 ? "" : "s") << " -> " << s.unique_sources
      << " distinct sources (" << s.compiled << " compiled, " << s.cache_hits << " cached" << remote_counts(s) << "), "
      << s.unique_blobs << " SPIR-V blobs" << kinds_served(s) << (s.output_changed ? "" : "; output unchanged");
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, " in %.2f s\n", s.seconds);
  out << seconds;
  if (s.renumbered_raw_ids > 0) {
    std::string features;
    for (const std::string& change : s.kind_changes) features += (features.empty() ? "" : ", ") + change;
    out << "shadergen: " << a.out_dir.string() << ": note: " << s.renumbered_raw_ids
        << " raw IDs map to other optimised IDs than in the previous output"
        << (features.empty() ? std::string() : " (feature kinds changed: " + features + ")")
        << "; anything keyed by optimised ID (a pipeline cache) is stale\n";
  }
  if (a.write_stats) out << format_build_stats(s);
}

}  // namespace

CLI::App* add_build_command(CLI::App& app, BuildCommandLine& line) {
  BuildOptions& o = line.options;
  CLI::App* build_cmd = app.add_subcommand("build", "Compile every permutation of a domain into an output folder");
  build_cmd->add_option("spec", o.spec_path, "Domain spec (JSON)")->required();
  build_cmd->add_option("--out,-o", o.out_dir,
                        "Output folder: manifest.json, spirv/, <name>.h/.cpp (replaced atomically); required "
                        "except with --shard");
  build_cmd->add_option("--variants", o.variants,
                        "Variants file: the raw combinations to build, one per line (replaces the spec's "
                        "\"variants_file\"; needed past 2^20 raw IDs)");
  build_cmd->add_option("-j,--jobs", o.jobs, "Parallel compile jobs (default: one per hardware thread)")
      ->check(CLI::Range(1u, 1024u));
  build_cmd->add_flag_callback(
      "--no-cache", [&o] { o.use_cache = false; }, "Ignore the content cache and compile everything (a cold build)");
  build_cmd->add_option("--cache-dir", o.cache_dir,
                        "Content cache folder (default: $SHADERGEN_CACHE_DIR, else $XDG_CACHE_HOME/shadergen, "
                        "else ~/.cache/shadergen)");
  build_cmd->add_option("--depfile", o.depfile, "Write a Make-style depfile listing the spec and every GLSL file read");
  build_cmd->add_option("--cpp-name", o.cpp_name, "Base name of the generated .h/.cpp (default: the domain name)");
  build_cmd->add_option("--namespace", o.cpp_namespace,
                        "C++ namespace of the generated code (default: the domain name)");
  build_cmd
      ->add_option("-D,--define", o.defines,
                   "NAME=VALUE (or NAME, meaning 1) for every shader of the domain; repeatable; adds to and "
                   "replaces the spec's \"defines\"")
      ->allow_extra_args(false);
  build_cmd->add_option("--target-env", o.target_env,
                        "vulkan1.0, vulkan1.1, vulkan1.2 or vulkan1.3: the Vulkan (and so SPIR-V) version to compile "
                        "and validate for (default: the spec's \"target_env\", else vulkan1.2)");
  build_cmd->add_flag("--strip-debug", o.strip_debug,
                      "Write blobs without debug instructions (names, sources, lines), as the spec's "
                      "\"strip_debug\": true; the manifest and registry keep the names");
  build_cmd->add_flag("--stats", o.write_stats, "Also write stats.json: per-stage counts and per-permutation timings");
  build_cmd->add_flag("-v,--verbose", o.verbose, "One progress line per compiled source");
  build_cmd
      ->add_option("--remote-cache", o.remote_cache_url,
                   "Content cache shared over HTTP, asked after the local one: GET/PUT URL/<key-prefix>/<key>")
      ->envname("SHADERGEN_REMOTE_CACHE");
  build_cmd->add_flag("--remote-cache-readonly", o.remote_cache_read_only,
                      "Only read the remote cache, never upload to it (developer machines)");
  build_cmd->add_option("--remote-cache-secret-file", line.remote_cache_secret_file,
                        "Sign uploads and accept only signed entries, with the secret in this file (default: "
                        "$SHADERGEN_REMOTE_CACHE_SECRET; none: entries are neither signed nor checked)");
  build_cmd
      ->add_option_function<double>(
          "--remote-cache-budget",
          [&o](double seconds) {
            o.remote_cache_budget = std::chrono::milliseconds(static_cast<long long>(seconds * 1000.0));
          },
          "Seconds the remote cache's requests may keep a build waiting in all before it is turned off "
          "for the rest of the build (default " +
              seconds_number(kDefaultRemoteCacheBudget) + "; each request waits at most " +
              seconds_number(kDefaultRemoteCacheRequestLimit) + ")")
      ->check(CLI::Range(0.0, 3600.0));
  build_cmd->add_option("--shard", line.shard,
                        "I/N: preprocess and compile only shard I (0-based) of N of the domain's compile jobs and "
                        "store their sources on --remote-cache; writes no output folder; exits 1 unless all of them "
                        "are on the server (docs/distributed.md)");
  build_cmd->add_flag("--require-remote-hits", line.require_remote_hits,
                      "The merge of a sharded build: compile nothing, take every source from the server alone "
                      "(never the local cache; no uploads), and fail (writing nothing) if any is missing or corrupt");
  build_cmd
      ->add_option("--shards", line.shards,
                   "With --require-remote-hits: how many shards filled the cache; each shard's record is "
                   "checked first (finished, same shadergen), and missing sources are counted per shard")
      ->check(CLI::Range(1u, kMaxShards));
  return build_cmd;
}

int run_build(BuildCommandLine& line, const std::atomic<bool>& interrupted, std::ostream& out, std::ostream& err) {
  BuildOptions& options = line.options;
  auto role = role_of(line);
  if (!role) return print_usage_error(role.errors().front(), err);
  options.role = *role;
  if (Status valid = validate(options); !valid) return print_usage_error(valid.errors().front(), err);
  auto secret = remote_cache_secret(line, err);
  if (!secret) return command_line::kExitError;
  options.remote_cache_secret = std::move(*secret);
  options.log = [&err](const std::string& text) { err << "shadergen: " << text << std::endl; };
  options.cancelled = [&interrupted] { return interrupted.load(); };
  auto summary = build(options);
  if (!summary) {
    if (interrupted.load()) {
      err << "shadergen: interrupted; " << options.out_dir.string() << " was left as it was\n";
      return command_line::kExitInterrupted;
    }
    return print_errors(summary.errors(), err);
  }
  if (summary->sharded)
    print_shard_summary(options, *summary, out);
  else
    print_summary(options, *summary, out);
  return command_line::kExitSuccess;
}

}  // namespace shadergen
