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
#include "cache/remote_stats.h"
#include "shadergen/build_options.h"
#include "shadergen/diagnostic.h"

namespace shadergen {

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
  // A shard preprocesses and compiles its range of the domain's compile jobs (`permutations`
  // counts those; `domain_permutations` all of the domain's), and their distinct sources.
  std::uint32_t domain_permutations = 0;
  std::uint32_t shard_sources = 0;    // distinct sources of this shard's jobs
  std::uint32_t shard_on_server = 0;  // of which the server held already (fetched and verified)
  std::uint32_t shard_uploaded = 0;   // of which compiled (or taken from the local cache) and uploaded now
  std::uint32_t shard_replaced = 0;   // of those, sources whose copy on the server failed the checks
  double seconds = 0.0;
  std::vector<PhaseTime> phases;  // in order; their sum is close to `seconds`
};

// Runs the whole build (validate(options) first). On failure nothing under out_dir (or the
// depfile) has changed.
Result<BuildSummary> build(const BuildOptions& options);

}  // namespace shadergen
