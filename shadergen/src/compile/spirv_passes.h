// spirv_passes.h - SPIRV-Tools optimisation and validation of compiled blobs.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "shadergen/diagnostic.h"
#include "shadergen/domain.h"

namespace shadergen {

// Validates against the environment of `env`. Errors quote the validator's message.
Status validate_spirv(std::span<const std::uint32_t> words, TargetEnv env = TargetEnv::vulkan1_2);

struct OptimisedBlob {
  std::vector<std::uint32_t> words;
  // The optimiser failed or produced a blob the validator rejects; `words` is then the
  // validated unoptimised input and `fallback_reason` says why.
  bool fell_back = false;
  std::string fallback_reason;
};

// Validates the input (an invalid input is an error), runs the performance passes, validates
// the result and falls back to the input if the optimised blob does not validate.
// Both the passes and the validator work in the environment of `env`.
Result<OptimisedBlob> optimise_and_validate(std::vector<std::uint32_t> words, TargetEnv env);

// `words` without debug instructions: OpName, OpMemberName, OpSource, OpSourceContinued,
// OpSourceExtension, OpString, OpLine, OpNoLine and OpModuleProcessed (SPIRV-Tools'
// strip-debug pass). Reflection reads names, so it runs on the unstripped blob first.
Result<std::vector<std::uint32_t>> strip_debug_info(std::span<const std::uint32_t> words, TargetEnv env);

// The optimisation recipe, part of every cache key (beside the target, which picks the
// passes' environment).
inline constexpr const char* kOptimiserRecipe = "spirv-tools-performance-passes/vulkan1.2";

}  // namespace shadergen
