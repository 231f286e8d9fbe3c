// codegen.h - the generated C++: a small header (LUT, bit names, registry accessor) and a
// source holding the SPIR-V words. Arrays live only in the source so that including the
// header stays cheap; identical blobs are stored once.
#pragma once

#include <filesystem>
#include <span>
#include <string>

#include "compile/compiled_domain.h"
#include "shadergen/diagnostic.h"

namespace shadergen {

class BlobSpill;

// The generated header. `cpp_namespace` may be qualified ("game::shaders"). Precondition: it is
// valid (see is_valid_namespace).
std::string generated_header(const CompiledDomain& domain, const std::string& cpp_namespace);
// A spec with "uber_shaders": one compiled domain per entry, in spec order (one without). The
// typed API and table once, then <entry>::registry() for each entry, and companions::<name>()
// for every companion. Precondition: `entries` is not empty and shares one plan.
std::string generated_header(std::span<const CompiledDomain> entries, const std::string& cpp_namespace);

// Writes the generated source to `file`, reading each blob's words from `spill` (the build's,
// which holds them all) one at a time. `header_name` is the file name the source includes
// ("split_second.h"). Errors name `file` or the spill's file that could not be read.
Status write_generated_source(std::span<const CompiledDomain> entries, const BlobSpill& spill,
                              const std::string& header_name, const std::string& cpp_namespace,
                              const std::filesystem::path& file);

bool is_valid_namespace(const std::string& name);

}  // namespace shadergen
