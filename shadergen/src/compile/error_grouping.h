// error_grouping.h - one diagnostic per distinct GLSL error, saying which permutations have it,
// instead of one copy per permutation.
#pragma once

#include <map>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "compile/compiled_domain.h"

namespace shadergen {

// A source line as the compiler saw it: (file, line) -> its preprocessed text.
using LiveLines = std::map<std::pair<std::string, int>, std::string>;

struct JobFailure {
  std::size_t job = 0;
  Diagnostics errors;
  // Every non-blank line of the job's preprocessed text; empty when unknown.
  LiveLines lines;
};

// Maps the lines of glslang's preprocessed text (one per source line, `#line N "file"` at
// include boundaries) to their file and line; `main_file` names the lines before any marker.
LiveLines live_lines(std::string_view preprocessed, const std::string& main_file);

// E.g. "uber/lighting.frag:212: error: 'x' : undeclared identifier (in 48 of 96 raw
// permutations: those with SOFT_SHADOW; e.g. raw 2 with SOFT_SHADOW)".
//
// glslang stops a shader at its first failing statement and adds follow-on messages at the
// same line; so per failure, a message at a file and line that an earlier message of that
// failure already had is folded into it, and the messages come in the order of the first
// error of each permutation. A permutation that stopped at an earlier error but whose
// preprocessed text holds an error's line, word for word, counts as hitting that error too.
// With `every_example` (the CLI's -v), an error whose permutations share no define set lists
// them all ("namely raw 1 with A, raw 6 with B C") instead of one example.
Diagnostics group_failures(const CompiledDomain& domain, const std::vector<JobFailure>& failures,
                           bool every_example = false);

// Where a problem occurs, for the parentheses after it: "in 4 of 8 raw permutations (vertex
// shader): those with FOG; e.g. raw 2 vertex with FOG". Permutations are counted by ID, so a
// program's two shaders count once, and the failing half is named. `failing` holds indices into
// `domain.jobs`; precondition: not empty.
std::string where_it_occurs(const CompiledDomain& domain, const std::set<std::size_t>& failing,
                            bool every_example = false);

}  // namespace shadergen
