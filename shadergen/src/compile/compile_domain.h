// compile_domain.h - compiling a whole domain: every permutation and companion preprocessed,
// deduplicated, compiled (or taken from the caches), optimised, validated and reflected, then
// the domain's layout and program checks. The result is a CompiledDomain (compiled_domain.h);
// nothing is written but cache entries.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "compile/compiled_domain.h"
#include "compile/shard_partition.h"
#include "shadergen/diagnostic.h"
#include "shadergen/domain.h"
#include "shadergen/permutations.h"

namespace shadergen {

class BlobSpill;
class ContentCache;
class InputCache;
class RemoteCache;

struct CompileOptions {
  unsigned jobs = 0;
  const ContentCache* cache = nullptr;  // nullptr: no cache
  const InputCache* inputs = nullptr;   // nullptr: no local input sets (the remote cache may share one)
  std::string input_key;                // input_set_key() of this build; empty: always preprocess
  bool verbose = false;
  std::function<void(const std::string&)> log;
  std::function<bool()> cancelled;
  RemoteCache* remote = nullptr;  // nullptr: no remote cache; else asked after a local miss
  // build --shard: only this shard's sources, each made sure of on the remote cache (needs
  // `remote`); the domain is not reflected or checked, and has no blobs.
  std::optional<ShardPlace> shard;
  // The merge: nothing is compiled; a source in neither cache fails the build (needs `remote`).
  bool require_remote_hits = false;
  std::uint32_t shards = 0;  // the merge names the shards that owned missing sources; 0: not
  // Where each distinct blob's words are written as soon as they are made (and, with strip_debug,
  // stripped); the domain's Blobs keep only their hash, size and reflection. Needed unless `shard`.
  BlobSpill* spill = nullptr;
};

// Preprocesses, deduplicates, compiles (or loads from the cache), optimises, validates and
// reflects every permutation, then checks the merged layout. Diagnostics about GLSL errors are
// grouped: one per distinct message, naming the permutations it occurs in.
Result<CompiledDomain> compile_domain(DomainSpec spec, PermutationPlan plan, const CompileOptions& options);

}  // namespace shadergen
