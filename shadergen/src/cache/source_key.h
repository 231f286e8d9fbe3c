// source_key.h - the part of a preprocessed text that decides its SPIR-V.
//
// glslang's preprocessed text keeps one line per source line (removed #ifdef blocks and
// directives become empty lines) and marks include boundaries with `#line N "file"`. Neither
// reaches the SPIR-V: without debug info, which shadergen never asks for, glslang emits no
// line numbers or file names (__LINE__ and __FILE__ are already expanded in the text). Keying
// the content cache on the text without them means that adding lines inside one #ifdef block
// recompiles only the permutations that keep the block, and that a shader moved or reached by
// another relative path still hits the cache.
#pragma once

#include <string>
#include <string_view>

namespace shadergen {

// `preprocessed` without whitespace-only lines and `#line` directives; every other line as it was.
std::string key_text(std::string_view preprocessed);

}  // namespace shadergen
