// error_grouping.h - one diagnostic per distinct GLSL error, saying which permutations have it,
// instead of one copy per permutation.
#pragma once

#include <vector>

#include "compiled_domain.h"

namespace shadergen {

struct JobFailure {
    std::size_t job = 0;
    Diagnostics errors;
};

// E.g. "uber/lighting.frag:212: error: 'x' : undeclared identifier (in 48 of 96 raw
// permutations: those with SOFT_SHADOW; e.g. raw 2 with SOFT_SHADOW)".
Diagnostics group_failures(const std::vector<CompileJob>& jobs, const std::vector<JobFailure>& failures);

}  // namespace shadergen
