// manifest.h - <out>/manifest.json and the other text outputs derived from a compiled domain.
#pragma once

#include <ostream>
#include <span>
#include <string>

#include "compile/compiled_domain.h"

namespace shadergen {

// Path of a blob relative to the output folder: "spirv/<first 16 hex digits of its hash>.spv".
std::string blob_relative_path(const Blob& blob);

// The manifest: raw and optimised permutations (id, defines, pruned, optimised, spirv, hash),
// companions, the merged pipeline layout. Deterministic: equal inputs give equal bytes.
// Written to `out` a permutation at a time (the string form is for small domains and tests).
void write_manifest(const CompiledDomain& domain, std::ostream& out);
// A spec with "uber_shaders": `entries` holds one compiled domain per entry, in spec order (one,
// without "uber_shaders"). The domain's members and the permutations' IDs, defines and table are
// written once; "uber_shaders" lists each entry's shader, blobs by permutation, companions,
// pipeline layout and blobs. Precondition: `entries` is not empty and shares one plan.
void write_manifest(std::span<const CompiledDomain> entries, std::ostream& out);
std::string write_manifest(const CompiledDomain& domain);

// Per-stage counts and per-source timings (`--stats`), likewise.
void write_stats(const CompiledDomain& domain, double seconds, std::ostream& out);
// With "uber_shaders": {"seconds", "uber_shaders": [each entry's counts and permutations]}.
void write_stats(std::span<const CompiledDomain> entries, double seconds, std::ostream& out);
std::string write_stats(const CompiledDomain& domain, double seconds);

// Make-syntax depfile: "<target>: <dep> <dep> ...", spaces escaped.
std::string write_depfile(const std::string& target, const CompiledDomain& domain);
// Every entry's dependencies, each once.
std::string write_depfile(const std::string& target, std::span<const CompiledDomain> entries);

}  // namespace shadergen
