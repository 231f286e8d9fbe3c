// kind_declarations.h - what shadergen adds to a permuted shader so that its features read the
// same under every kind (docs/spec-format.md, "Kinds").
//
// A variant feature is a define in the preamble, as ever. A specialization feature becomes
// `layout(constant_id = K) const bool|int NAME = <first value>;`, a branch feature a member of
// the uniform block at "branch_block" and a macro NAME that reads it. Both need declarations,
// which GLSL allows only after `#version`: they are inserted into the shader's text there (with a
// `#line` so that messages keep the file's own line numbers).
#pragma once

#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "shadergen/domain.h"

namespace shadergen {

struct KindDeclarations {
  // Preamble lines: identifier values of value-style variants (`#define PBR 1`).
  std::string macros;
  // Declarations after `#version`: specialization constants, identifier values of
  // specialization and branch features (`const int PBR = 1;`), the branch block and its
  // readers (`#define FOG (shadergen_branch.FOG != 0u)`).
  std::string declarations;
  // The defines of value-style boolean variants (see boolean_value_defines()).
  std::set<std::string> value_booleans;
};

// Empty when every feature is a presence-style variant (today's text, byte for byte).
KindDeclarations kind_declarations(const DomainSpec& spec);

// The name of the branch block's instance and type in the shader.
inline constexpr std::string_view kBranchBlockInstance = "shadergen_branch";
inline constexpr std::string_view kBranchBlockType = "ShadergenBranchBlock";

// The integer a value index stands for at run time: a numeric value as written, an identifier's
// index. Precondition: index < f.values.size().
std::int32_t value_number(const RawFeature& f, std::uint32_t index);

// `defines` ("NAME=0|1" for a value-style boolean, as raw_defines() lists it) as the preamble
// writes them: such a boolean's value becomes `(1 == 1)` or `(0 == 1)`, which both `#if NAME` and
// `if (NAME)` read (`if (1)` is no GLSL). The others are unchanged.
std::vector<std::string> boolean_value_defines(std::vector<std::string> defines, const KindDeclarations& kinds);

// `text` with `declarations` inserted after its `#version` line (at the top when it has none),
// followed by a `#line` that gives the next line its number in `text`. `declarations` ends with
// a newline. Returns `text` unchanged when `declarations` is empty.
std::string insert_declarations(std::string_view text, std::string_view declarations);

}  // namespace shadergen
