// shadergen/build.h - `shadergen build`: a domain spec to validated SPIR-V, a manifest and
// generated C++, written atomically into an output folder.
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "base/phase_clock.h"
#include "cache/remote_defaults.h"
#include "cache/remote_stats.h"
#include "shadergen/diagnostic.h"

namespace shadergen {

// `--shard I/N`: part I (0-based) of N of a domain's distinct sources.
struct Shard {
  std::uint32_t index = 0;
  std::uint32_t count = 1;
};
inline constexpr std::uint32_t kMaxShards = 4096;

struct BuildOptions {
  std::filesystem::path spec_path;
  std::filesystem::path out_dir;
  // `--variants`: the raw combinations to build, one per line; replaces the spec's
  // "variants_file". Empty: the spec's, or every raw ID (docs/spec-format.md).
  std::filesystem::path variants;
  unsigned jobs = 0;                // 0 = one per hardware thread
  bool use_cache = true;            // false: compile everything (a cold build)
  std::filesystem::path cache_dir;  // empty: default_cache_directory()
  std::filesystem::path depfile;    // empty: none. Make syntax, target = the generated header
  std::string cpp_name;             // base name of the generated .h/.cpp; empty: the domain name
  std::string cpp_namespace;        // C++ namespace of the generated code; empty: the domain name
  // `--define` arguments, "NAME=VALUE" or "NAME" (= 1): they add to and replace the spec's
  // top-level "defines", so they reach every shader of the domain. They change the outputs
  // only through the preprocessed text, which is what the content cache is keyed on.
  std::vector<std::string> defines;
  // `--target-env`: "vulkan1.0" ... "vulkan1.3"; empty: the spec's "target_env" (default vulkan1.2).
  std::string target_env;
  // `--strip-debug`: as the spec's "strip_debug": true (either one strips). The blobs lose
  // OpName, OpMemberName, OpSource, OpString, OpLine and OpModuleProcessed; the manifest and
  // the registry keep the names (reflection runs first). The cache keeps unstripped blobs.
  bool strip_debug = false;
  bool write_stats = false;  // also write <out>/stats.json (timings: not deterministic)
  bool verbose = false;      // one progress line per compiled source
  // A content cache shared over HTTP: GET/PUT <url>/<key[0:2]>/<key>, asked after a local miss,
  // given every entry compiled here unless read-only. Empty: none; unused without use_cache,
  // except by a shard or a merge, which then skip only the local cache.
  // Precondition: empty or an http:// or https:// URL (else build() fails naming it).
  // Credentials in it ("user:password@") are never printed; ~/.netrc can hold them instead.
  std::string remote_cache_url;
  bool remote_cache_read_only = false;
  // Not empty: every upload is signed with HMAC-SHA256 under this secret, and only entries so
  // signed are used (docs/cli.md, "trust model"). Never printed.
  std::string remote_cache_secret;
  // The waiting time the remote cache's requests may cost this build together; once spent, the
  // rest of the build does not use it. Each request also waits at most remote_cache_request_limit.
  std::chrono::milliseconds remote_cache_budget = kDefaultRemoteCacheBudget;
  std::chrono::milliseconds remote_cache_request_limit = kDefaultRemoteCacheRequestLimit;
  // Set: compile only this shard's distinct sources (after pruning, collapse and dedup) and
  // store each on the remote cache; nothing is written under out_dir (which may be empty).
  // The build fails, naming how many, unless every source of the shard is on the server.
  // Preconditions: a remote cache that is not read-only; index < count <= kMaxShards.
  std::optional<Shard> shard;
  // The merge of a sharded build: compile nothing. A distinct source found in neither the local
  // nor the remote cache (or failing verification) is missing, and the build then fails naming
  // how many, per shard when `shards` is not 0, and writes nothing. Needs a remote cache.
  bool require_remote_hits = false;
  std::uint32_t shards = 0;  // how many shards filled the cache (for the merge's message); 0: unknown
  // Receives progress lines (the CLI prints them on stderr). May be empty.
  std::function<void(const std::string&)> log;
  // Polled between jobs; when it returns true the build stops and fails, output untouched.
  std::function<bool()> cancelled;
};

// What a build did and how long each phase took. The CLI prints it (`--stats` too: cli/build_stats.h).
struct BuildSummary {
  std::uint32_t raw = 0;     // raw permutations in the domain
  std::uint32_t pruned = 0;  // of which impossible
  std::uint32_t optimised = 0;
  std::uint32_t companions = 0;
  std::uint32_t unique_sources = 0;  // distinct preprocessed texts
  std::uint32_t compiled = 0;        // of which compiled now (cache misses)
  std::uint32_t cache_hits = 0;
  std::uint32_t unique_blobs = 0;  // distinct SPIR-V blobs written
  std::uint32_t optimiser_fallbacks = 0;
  // With specialization or branch features (else 0): the most pipelines one blob serves
  // (distinct specialization data) and the most branch values one blob takes.
  std::uint32_t most_pipelines_per_blob = 0;
  std::uint32_t most_branch_values_per_blob = 0;
  std::uint32_t permutations = 0;  // compile jobs: unpruned raw + optimised + companions
  std::uint32_t recompiled = 0;    // of which compiled now (their preprocessed source missed)
  std::uint32_t reused = 0;        // of which taken from the cache
  bool inputs_reused = false;      // every input unchanged: preprocessing was skipped
  bool output_changed = false;     // false when every output file already had these bytes
  // Against the manifest this build replaced: how many raw IDs now have another optimised ID
  // (anything keyed by optimised ID, a pipeline cache, is then stale), and the features that
  // moved between variant and another kind, "FOG (variant -> specialization)". 0 and empty for a
  // first build, one that renumbers nothing, or a domain that is not collapsed.
  std::uint32_t renumbered_raw_ids = 0;
  std::vector<std::string> kind_changes;
  // With a remote cache only: what it did (its `fetched` entries are among cache_hits).
  std::optional<RemoteCacheStats> remote;
  // A shard (`--shard I/N`): its place and what became of its sources.
  bool sharded = false;
  std::uint32_t shard_index = 0, shard_count = 0;
  std::uint32_t shard_sources = 0;    // distinct sources this shard owns
  std::uint32_t shard_on_server = 0;  // of which the server held already (verified, or offered from the local cache)
  std::uint32_t shard_uploaded = 0;   // of which compiled (or taken from the local cache) and uploaded now
  double seconds = 0.0;
  std::vector<PhaseTime> phases;  // in order; their sum is close to `seconds`
};

// Runs the whole build. On failure nothing under out_dir (or the depfile) has changed.
Result<BuildSummary> build(const BuildOptions& options);

}  // namespace shadergen
