// manifest.h - <out>/manifest.json and the other text outputs derived from a compiled domain.
#pragma once

#include <ostream>
#include <string>

#include "compile/compiled_domain.h"

namespace shadergen {

// Path of a blob relative to the output folder: "spirv/<first 16 hex digits of its hash>.spv".
std::string blob_relative_path(const Blob& blob);

// The manifest: raw and optimised permutations (id, defines, pruned, optimised, spirv, hash),
// companions, the merged pipeline layout. Deterministic: equal inputs give equal bytes.
// Written to `out` a permutation at a time (the string form is for small domains and tests).
void write_manifest(const CompiledDomain& domain, std::ostream& out);
std::string write_manifest(const CompiledDomain& domain);

// Per-stage counts and per-source timings (`--stats`), likewise.
void write_stats(const CompiledDomain& domain, double seconds, std::ostream& out);
std::string write_stats(const CompiledDomain& domain, double seconds);

// Make-syntax depfile: "<target>: <dep> <dep> ...", spaces escaped.
std::string write_depfile(const std::string& target, const CompiledDomain& domain);

}  // namespace shadergen
