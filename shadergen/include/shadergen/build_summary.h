// shadergen/build_summary.h - what a build did and how long each phase took: the result of
// shadergen::build() (shadergen/build.h), and what `--stats` prints.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace shadergen {

// Wall time of one phase of a build ("parse spec", "preprocess", "compile or load", ...).
struct PhaseTime {
  std::string name;
  double ms = 0.0;
};

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
  std::uint32_t permutations = 0;    // compile jobs: unpruned raw + optimised + companions
  std::uint32_t recompiled = 0;      // of which compiled now (their preprocessed source missed)
  std::uint32_t reused = 0;          // of which taken from the cache
  bool inputs_reused = false;        // every input unchanged: preprocessing was skipped
  bool output_changed = false;       // false when every output file already had these bytes
  bool remote_cache = false;         // a remote cache was configured; then the three counts:
  std::uint32_t remote_fetched = 0;  // of cache_hits, entries taken from the remote cache
  std::uint32_t remote_uploaded = 0;
  std::uint32_t remote_failed = 0;  // requests without a usable answer, and rejected entries
  // A shard (`--shard I/N`): its place and what became of its sources.
  bool sharded = false;
  std::uint32_t shard_index = 0, shard_count = 0;
  std::uint32_t shard_sources = 0;    // distinct sources this shard owns
  std::uint32_t shard_on_server = 0;  // of which the server held already (verified, or offered from the local cache)
  std::uint32_t shard_uploaded = 0;   // of which compiled (or taken from the local cache) and uploaded now
  double seconds = 0.0;
  std::vector<PhaseTime> phases;  // in order; their sum is close to `seconds`
};

// Two lines for `--stats`: permutations recompiled vs reused, whether preprocessing was
// skipped, and the phase timings. Ends with a newline.
std::string format_build_stats(const BuildSummary& summary);

}  // namespace shadergen
