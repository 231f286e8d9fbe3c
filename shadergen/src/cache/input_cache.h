// input_cache.h - the second-level cache: from an unchanged input set straight to the
// content-cache keys, so a warm build never starts glslang.
//
// The content cache (cache.h) is keyed by preprocessed text, so finding its entries normally
// means preprocessing every permutation. An input-set entry remembers, for one spec (its path,
// its bytes, the working folder and the tool versions), every file the preprocessor looked at
// last time with the SHA-256 of the bytes it read (and every include-path probe that found
// nothing), plus the content-cache key of each compile job. When every one of those files
// still has those bytes and every probe still finds nothing, the preprocessed texts are the
// same, so the keys are too.
//
// Entries are verified like content-cache entries: magic, their own key, counts and a SHA-256
// over the whole text. A truncated, corrupted or foreign entry reads as a miss.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cache/cache.h"
#include "cache/input_read.h"
#include "shadergen/diagnostic.h"
#include "shadergen/domain.h"

namespace shadergen {

struct InputSet {
  std::vector<InputRead> files;          // sorted by path, one entry per path
  std::vector<std::string> source_keys;  // content-cache key of each compile job, in job order
};

// The entry key of a build of the spec at `spec_path` (as given) whose bytes hash to
// `spec_digest`, run from the current working folder by the tools `tools` describes with
// `settings`: the text of every build option that changes preprocessing but is not in the
// spec's bytes (the `--define`s), so that a build with other options never reuses the keys.
std::string input_set_key(const CacheKeyParts& tools, const std::filesystem::path& spec_path,
                          std::string_view spec_digest, std::string_view settings);

// The key of shard `index` of `count`'s part of the input set `input_key`: the reads of the
// shard's own compile jobs and their content keys (shard_partition.h), which a shard uploads so
// that the merge joins the parts instead of preprocessing the domain again.
std::string input_set_part_key(std::string_view input_key, std::uint32_t index, std::uint32_t count);

// The parts of shards 0..N-1 (`parts`, in shard order) as one input set: each path once, the
// source keys one part after another. An error names the path two shards read different bytes
// of (a file changed while the shards ran).
Result<InputSet> join_input_parts(std::vector<InputSet> parts);

// Merges the reads of every preprocessed job into one sorted list. Fails (nullopt) when two
// jobs saw different bytes for one path: a file changed during the build, so nothing may be
// remembered about it.
std::optional<std::vector<InputRead>> merge_reads(const std::vector<std::vector<InputRead>>& per_job);

// True when every file still holds the bytes recorded and every failed probe still fails.
bool inputs_unchanged(const std::vector<InputRead>& files);

std::string encode_input_set(std::string_view key, const InputSet& set);
std::optional<InputSet> decode_input_set(std::string_view key, std::string_view bytes);

class InputCache {
 public:
  InputCache() = default;  // disabled: every lookup misses, stores are dropped
  explicit InputCache(const std::filesystem::path& cache_dir) : directory_(cache_dir / "inputs") {}

  bool enabled() const { return !directory_.empty(); }
  std::filesystem::path entry_path(std::string_view key) const { return directory_ / std::string(key); }

  std::optional<InputSet> load(std::string_view key) const;
  // Errors name the entry path; callers treat them as warnings.
  Status store(std::string_view key, const InputSet& set) const;

 private:
  std::filesystem::path directory_;
};

}  // namespace shadergen
