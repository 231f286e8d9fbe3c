// manifest.h - <out>/manifest.json and the other text outputs derived from a compiled domain.
#pragma once

#include <string>

#include "compile/compiled_domain.h"

namespace shadergen {

// Path of a blob relative to the output folder: "spirv/<first 16 hex digits of its hash>.spv".
std::string blob_relative_path(const Blob& blob);

// The manifest: raw and optimised permutations (id, defines, pruned, optimised, spirv, hash),
// companions, the merged pipeline layout. Deterministic: equal inputs give equal bytes.
std::string write_manifest(const CompiledDomain& domain);

// Per-stage counts and per-source timings (`--stats`).
std::string write_stats(const CompiledDomain& domain, double seconds);

// Make-syntax depfile: "<target>: <dep> <dep> ...", spaces escaped.
std::string write_depfile(const std::string& target, const CompiledDomain& domain);

}  // namespace shadergen
