// defines.h - the one textual form of a GLSL define everywhere in shadergen.
//
// A define is "NAME" (compiled as `#define NAME 1`, the form boolean features have always
// used) or "NAME=VALUE" (compiled as `#define NAME VALUE`). Keeping one string form means a
// permutation's define list reads the same in the manifest, the registry, `shadergen list`
// and diagnostics, whether its defines are switches, values or fixed settings.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "shadergen/diagnostic.h"

namespace shadergen {

// [A-Za-z_][A-Za-z0-9_]*, at most 64 characters.
bool is_identifier(std::string_view text);

// The part before '=' (the whole text when there is none).
std::string_view define_name(std::string_view define);

// The preamble line for `define`, newline included: "#define NAME 1\n" or "#define NAME VALUE\n".
std::string define_line(std::string_view define);

// Why `name` cannot be a macro name (empty when it can): not an identifier, or reserved by
// GLSL (a GL_ prefix or a double underscore).
std::string define_name_problem(std::string_view name);

// Why `value` cannot be a macro body (empty when it can): a line break or another control
// character (the body must stay on the #define line), or longer than 1,024 characters.
std::string define_value_problem(std::string_view value);

// A `--define` argument, "NAME=VALUE" or "NAME" (meaning NAME=1), checked and returned as
// "NAME=VALUE". Errors name the option and the argument.
Result<std::string> parse_define_argument(std::string_view argument);

// `base` with every define of `overrides` replacing the one of the same name in place, or
// appended when `base` has none. Precondition: every entry has the "NAME[=VALUE]" form.
std::vector<std::string> override_defines(std::vector<std::string> base, const std::vector<std::string>& overrides);

}  // namespace shadergen
