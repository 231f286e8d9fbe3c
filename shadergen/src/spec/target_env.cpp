#include "spec/target_env.h"

#include <array>

namespace shadergen {
namespace {

struct TargetEnvInfo {
  TargetEnv env;
  std::string_view name;
  unsigned spirv_minor;
};

// Vulkan 1.0 consumes SPIR-V 1.0, 1.1 up to 1.3, 1.2 up to 1.5, 1.3 up to 1.6; shadergen
// emits the newest each allows, as glslang's --target-env does.
constexpr std::array<TargetEnvInfo, 4> kTargets{{
    {TargetEnv::vulkan1_0, "vulkan1.0", 0},
    {TargetEnv::vulkan1_1, "vulkan1.1", 3},
    {TargetEnv::vulkan1_2, "vulkan1.2", 5},
    {TargetEnv::vulkan1_3, "vulkan1.3", 6},
}};

const TargetEnvInfo& info(TargetEnv env) { return kTargets[static_cast<std::size_t>(env)]; }

}  // namespace

std::string_view target_env_name(TargetEnv env) { return info(env).name; }

bool parse_target_env(std::string_view name, TargetEnv& env) {
  for (const TargetEnvInfo& target : kTargets)
    if (target.name == name) {
      env = target.env;
      return true;
    }
  return false;
}

std::string_view target_env_choices() { return "vulkan1.0, vulkan1.1, vulkan1.2 or vulkan1.3"; }

std::string target_description(TargetEnv env) {
  return std::string(info(env).name) + "/spv1." + std::to_string(info(env).spirv_minor);
}

unsigned spirv_version_word(TargetEnv env) { return 0x00010000u | (info(env).spirv_minor << 8); }

}  // namespace shadergen
