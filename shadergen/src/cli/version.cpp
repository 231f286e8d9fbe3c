#include "cli/version.h"

#include <spirv_cross_c.h>

#include "compile/toolchain.h"

namespace shadergen {

std::string version_text() {
  // The same versions the cache keys carry, so the two never disagree.
  CacheKeyParts parts = current_cache_key_parts();
  return "shadergen " SHADERGEN_VERSION " (glslang " + parts.glslang_version + ", SPIRV-Tools " +
         parts.spirv_tools_version + ", SPIRV-Cross C API " + std::to_string(SPVC_C_API_VERSION_MAJOR) + "." +
         std::to_string(SPVC_C_API_VERSION_MINOR) + "." + std::to_string(SPVC_C_API_VERSION_PATCH) + ")";
}

}  // namespace shadergen
