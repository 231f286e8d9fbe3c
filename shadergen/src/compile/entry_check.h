// entry_check.h - whether a blob from a remote cache is fit for a build: it validates for the
// build's target environment and its entry point is of the expected stage. (Reflection follows
// in the build itself, before any remote blob is used or kept locally: compile_domain.cpp.)
//
// This catches random words behind a recomputed checksum and shaders of another stage; a valid
// shader of the right stage from elsewhere can only be caught when the build's checks of the
// whole domain fail (compile_domain then compiles the server's entries here), or by signed
// entries (signed_entry.h), which keep out anyone without the team's secret.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "shadergen/domain.h"

namespace shadergen {

// Empty when fit, else why not (the validator's message, or the missing stage).
std::string unfit_reason(std::span<const std::uint32_t> words, Stage stage, TargetEnv env);

// The stage half of unfit_reason() alone, for a signed entry: its writer held the team's secret
// and validated the blob for the same key (target and toolchain included) before signing it,
// so validating it again would only repeat the writer's work (docs/distributed.md, "Trust").
std::string wrong_stage_reason(std::span<const std::uint32_t> words, Stage stage);

}  // namespace shadergen
