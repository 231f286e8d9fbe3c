// cpp_text.h - text that the code generator writes into C++: every string from a spec, a shader
// or a path goes through here, so no name (a newline, a quote, a trailing backslash) can
// break the generated source.
#pragma once

#include <string>
#include <string_view>

#include "spec/cpp_names.h"  // enumerator_name(): the spec checks the names it makes

namespace shadergen {

// A C++ string literal, quotes included, that reads back as `text`: quote and backslash
// escaped, \n \r \t as such, other control bytes as three-digit octal escapes (which cannot
// swallow a following digit). Bytes from 0x80 up are kept (UTF-8 source).
std::string cpp_string_literal(std::string_view text);

// `text` for a `//` comment: the same escapes without the quotes, so it stays on its line
// (no newline, no backslash at the end splicing the next line into the comment).
std::string cpp_comment_text(std::string_view text);

}  // namespace shadergen
