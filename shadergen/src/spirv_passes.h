// spirv_passes.h - SPIRV-Tools optimisation and validation of compiled blobs.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "shadergen/diagnostic.h"

namespace shadergen {

// Validates against the Vulkan 1.2 environment. Errors quote the validator's message.
Status validate_spirv(std::span<const std::uint32_t> words);

struct OptimisedBlob {
    std::vector<std::uint32_t> words;
    // The optimiser failed or produced a blob the validator rejects; `words` is then the
    // validated unoptimised input and `fallback_reason` says why.
    bool fell_back = false;
    std::string fallback_reason;
};

// Validates the input (an invalid input is an error), runs the performance passes, validates
// the result and falls back to the input if the optimised blob does not validate.
Result<OptimisedBlob> optimise_and_validate(std::vector<std::uint32_t> words);

// The optimisation recipe, part of every cache key.
inline constexpr const char* kOptimiserRecipe = "spirv-tools-performance-passes/vulkan1.2";

}  // namespace shadergen
