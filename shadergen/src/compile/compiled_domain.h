// compiled_domain.h - the in-memory result of compiling a domain, before anything is written.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "base/phase_clock.h"
#include "cache/remote_cache.h"
#include "compile/layout_check.h"
#include "compile/reflection.h"
#include "shadergen/diagnostic.h"
#include "shadergen/domain.h"
#include "shadergen/permutations.h"

namespace shadergen {

// One distinct SPIR-V blob; permutations with equal words share it. Its words are not kept in
// memory: they are in the build's BlobSpill (blob_spill.h), under `hash`.
struct Blob {
  std::size_t word_count = 0;
  std::string hash;  // SHA-256 of the words, hex
  ReflectionInfo reflection;
  bool fell_back = false;
  std::string fallback_reason;
};

enum class JobKind { raw, optimised, companion };

// One thing to compile: a raw or optimised permutation or a companion shader. It holds no
// strings: its defines, shader file and label follow from its kind and ID, and CompiledDomain
// computes them when needed (defines_of(), path_of(), label_of()), so that what a build keeps
// grows by a few words per permutation (issue 34).
struct CompileJob {
  JobKind kind = JobKind::raw;
  std::uint32_t id = 0;  // raw/optimised ID, or companion index
  Stage stage = Stage::fragment;
  bool vertex_half = false;  // the vertex half of a "program" permutation
  // Filled while compiling:
  int source = -1;  // index of its distinct preprocessed source
  int blob = -1;    // index into CompiledDomain::blobs
  double preprocess_ms = 0.0;
};

struct SourceRecord {
  std::string key;  // cache key
  std::size_t first_job = 0;
  bool cache_hit = false;
  double compile_ms = 0.0;
  int blob = -1;
  bool remote_hit = false;  // the cache hit came from the remote cache
};

// What a shard (CompileOptions::shard) did with the sources it owns.
struct ShardOutcome {
  std::uint32_t index = 0, count = 0;
  std::uint32_t sources = 0;    // distinct sources the shard owns
  std::uint32_t on_server = 0;  // the server had them already
  std::uint32_t uploaded = 0;   // stored on the server now
  std::uint32_t replaced = 0;   // of which the server held a copy that failed the checks
};

struct CompiledDomain {
  DomainSpec spec;
  PermutationPlan plan;
  std::vector<CompileJob> jobs;
  // Index into `jobs` by position in plan.raw and plan.optimised (the ID itself when the domain
  // is enumerated) and by companion index; -1: none, e.g. pruned.
  std::vector<int> raw_jobs, optimised_jobs, companion_jobs;
  std::vector<int> raw_vertex_jobs, optimised_vertex_jobs;  // "program" form only
  std::vector<SourceRecord> sources;
  std::vector<Blob> blobs;
  MergedLayout layout;
  std::vector<std::filesystem::path> dependencies;  // spec, shaders, includes; sorted, unique
  bool inputs_reused = false;                       // source keys came from the input-set cache, no preprocessing
  std::vector<PhaseTime> phases;                    // preprocess (or input check), compile or load, reflect, layout
  std::optional<RemoteCacheStats> remote;           // with a remote cache only
  std::optional<ShardOutcome> shard;                // a shard's build only (then `blobs` is empty)

  // What a job is compiled from. Precondition: `job` is one of `jobs` (its ID is in `plan`, or
  // it indexes spec.companions).
  // Its GLSL defines ("NAME" or "NAME=VALUE"): a raw ID's from the spec's features
  // (raw_defines()), an optimised ID's from the plan, a companion's from the spec.
  std::vector<std::string> defines_of(const CompileJob& job) const;
  // Its shader file: the uber-shader, the "program" form's vertex shader, or the companion's.
  const std::filesystem::path& path_of(const CompileJob& job) const;
  // "raw 37", "optimised 5 vertex", "companion tile".
  std::string label_of(const CompileJob& job) const;

  // Blob of raw ID `id`, or nullptr when pruned. Likewise for optimised IDs and companions.
  const Blob* raw_blob(std::uint32_t id) const;
  const Blob* optimised_blob(std::uint32_t id) const;
  const Blob* companion_blob(std::size_t index) const;
  // The vertex half of a "program" permutation, or nullptr.
  const Blob* raw_vertex_blob(std::uint32_t id) const;
  const Blob* optimised_vertex_blob(std::uint32_t id) const;
};

// What one blob serves in a domain with specialization or branch features: the raw IDs drawn
// with it (through the lookup table when collapsed), the pipelines they need (distinct
// specialization data) and the distinct branch values they upload.
struct BlobServes {
  std::size_t raw_ids = 0;
  std::size_t pipelines = 0;
  std::size_t branch_values = 0;
};

// Indexed like d.blobs; all zero for the blobs no raw ID draws with, and for every blob of a
// variant-only domain (then nothing is counted).
std::vector<BlobServes> blob_serves(const CompiledDomain& d);

}  // namespace shadergen
