// input_read.h - one file the preprocessor looked at, as the input-set cache (input_cache.h)
// records it and the compiler (compile/glsl_compiler.h) reports it.
#pragma once

#include <filesystem>
#include <string>

namespace shadergen {

// One file the preprocessor looked at: opened (with the SHA-256 of the bytes it read) or
// probed on the include search path and not found. Together these decide the text.
struct InputRead {
  std::filesystem::path path;
  bool found = false;
  std::string digest;  // hex; empty when not found
};

}  // namespace shadergen
