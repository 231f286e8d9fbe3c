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
#include "shadergen/build_options.h"
#include "shadergen/diagnostic.h"
#include "shadergen/domain.h"
#include "shadergen/permutations.h"

namespace shadergen {

class BlobSpill;
class ContentCache;
class InputCache;
class RemoteCache;

// What compile_domain() works with: the build's options (the one options object: jobs, verbose,
// log, cancellation and role come from there) and the caches and spill the driver opened.
struct CompileOptions {
  const BuildOptions* build = nullptr;  // not null; the role decides shard and merge:
  // a shard makes sure each of its sources is on the remote cache (needs `remote`), and the
  // domain is then not reflected or checked and has no blobs; a merge compiles nothing and
  // takes every source from the server (needs `remote`).
  const ContentCache* cache = nullptr;  // nullptr: no cache
  const InputCache* inputs = nullptr;   // nullptr: no local input sets (the remote cache may share one)
  std::string input_key;                // input_set_key() of this build; empty: always preprocess
  RemoteCache* remote = nullptr;        // nullptr: no remote cache; else asked after a local miss
  // Where each distinct blob's words are written as soon as they are made (and, with strip_debug,
  // stripped); the domain's Blobs keep only their hash, size and reflection. Needed unless a shard.
  BlobSpill* spill = nullptr;
};

// Preprocesses, deduplicates, compiles (or loads from the cache), optimises, validates and
// reflects every permutation, then checks the merged layout. Diagnostics about GLSL errors are
// grouped: one per distinct message, naming the permutations it occurs in.
Result<CompiledDomain> compile_domain(DomainSpec spec, PermutationPlan plan, const CompileOptions& options);

}  // namespace shadergen
