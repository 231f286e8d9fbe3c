// version.h - what `shadergen --version` prints: the tool and the compiler libraries it links,
// since a blob depends on all of them.
#pragma once

#include <string>

namespace shadergen {

// "shadergen 0.1.0 (glslang 12.0.0, SPIRV-Tools v2023.1, SPIRV-Cross C API 0.54.0)". SPIRV-Cross
// has no release number of its own in its headers; its C API version identifies the release.
std::string version_text();

}  // namespace shadergen
