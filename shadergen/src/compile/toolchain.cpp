#include "compile/toolchain.h"

#include <glslang/build_info.h>
#include <spirv-tools/libspirv.h>

#include "compile/glsl_compiler.h"
#include "compile/spirv_passes.h"

namespace shadergen {

CacheKeyParts current_cache_key_parts() {
  // A package upgrade of either compiler library may change the blobs: new keys.
  return CacheKeyParts{SHADERGEN_VERSION,
                       std::to_string(GLSLANG_VERSION_MAJOR) + "." + std::to_string(GLSLANG_VERSION_MINOR) + "." +
                           std::to_string(GLSLANG_VERSION_PATCH) + GLSLANG_VERSION_FLAVOR,
                       spvSoftwareVersionString(), std::string(kTargetDescription), std::string(kOptimiserRecipe)};
}

}  // namespace shadergen
