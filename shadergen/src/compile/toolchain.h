// toolchain.h - the compilers this build of shadergen drives, described as the content cache's
// keys name them (cache/cache.h): the cache knows keys, the compile area knows its compilers.
#pragma once

#include "cache/cache.h"

namespace shadergen {

// This build of the tool: its version, the glslang and SPIRV-Tools libraries linked in, the
// default target and the optimiser recipe.
CacheKeyParts current_cache_key_parts();

}  // namespace shadergen
