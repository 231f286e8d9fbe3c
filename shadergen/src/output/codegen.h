// codegen.h - the generated C++: a small header (LUT, bit names, registry accessor) and a
// source holding the SPIR-V words. Arrays live only in the source so that including the
// header stays cheap; identical blobs are stored once.
#pragma once

#include <string>

#include "compile/compiled_domain.h"

namespace shadergen {

struct GeneratedCpp {
  std::string header;
  std::string source;
};

// `header_name` is the file name the source includes ("split_second.h"); `cpp_namespace` may
// be qualified ("game::shaders"). Precondition: both are valid (see is_valid_namespace).
GeneratedCpp generate_cpp(const CompiledDomain& domain, const std::string& header_name,
                          const std::string& cpp_namespace);

bool is_valid_namespace(const std::string& name);

}  // namespace shadergen
