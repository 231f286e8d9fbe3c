// target_env.h - what one TargetEnv (shadergen/domain.h) means to each library shadergen
// drives: glslang's client and SPIR-V versions, SPIRV-Tools' environment, and the text that
// stands for it in cache keys.
#pragma once

#include <string>

#include "shadergen/domain.h"

namespace shadergen {

// "vulkan1.2/spv1.5": part of every content-cache key, so blobs for two targets never mix.
std::string target_description(TargetEnv env);

// The SPIR-V version the target implies, as the version word of a module header (0x00010500).
unsigned spirv_version_word(TargetEnv env);

}  // namespace shadergen
