// glsl_compiler.h - GLSL to SPIR-V through the glslang library, in process.
//
// Two steps, because deduplication needs the first alone: preprocess() expands #include and
// the feature #defines to the exact text the compiler will see (permutations whose text is
// equal produce equal SPIR-V, so they are compiled once), and compile() turns a permutation
// into unoptimised SPIR-V. Both record every file glslang opened, for the depfile.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "cache/input_read.h"
#include "shadergen/diagnostic.h"
#include "shadergen/domain.h"
#include "shadergen/registry.h"

namespace shadergen {

struct GlslSource {
  std::filesystem::path path;  // the shader file
  Stage stage = Stage::fragment;
  std::vector<std::filesystem::path> include_dirs;  // searched after the including file's folder
  std::vector<std::string> defines;                 // "NAME" (= 1) or "NAME=VALUE" (defines.h)
  // The domain's fixed defines, same form, ahead of `defines`; none has a name in `defines`.
  std::vector<std::string> fixed_defines;
  TargetEnv target = TargetEnv::vulkan1_2;  // Vulkan and SPIR-V versions
  // A permuted shader's kind declarations (spec/kind_declarations.h): `kind_macros` end the
  // preamble, `kind_declarations` are inserted after the file's #version line.
  std::string kind_macros = {};
  std::string kind_declarations = {};
};

struct Preprocessed {
  std::string text;                             // what the parser will see; the dedup key
  std::vector<std::filesystem::path> includes;  // every file #include opened, in order
  std::vector<InputRead> reads;                 // the shader, its includes and failed probes
};

// The default target (Vulkan 1.2, SPIR-V 1.5), as target_description() writes it; GLSL 450
// unless the shader says otherwise.
inline constexpr const char* kTargetDescription = "vulkan1.2/spv1.5";

// Thread-safe (each call owns its glslang objects). Diagnostics carry the original file
// (the shader or the include it occurred in) and line.
Result<Preprocessed> preprocess(const GlslSource& source);
Result<std::vector<std::uint32_t>> compile(const GlslSource& source);

}  // namespace shadergen
