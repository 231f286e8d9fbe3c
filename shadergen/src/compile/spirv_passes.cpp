#include "compile/spirv_passes.h"

#include <spirv-tools/libspirv.hpp>
#include <spirv-tools/optimizer.hpp>

namespace shadergen {
namespace {

spv_target_env environment(TargetEnv env) {
  switch (env) {
    case TargetEnv::vulkan1_0: return SPV_ENV_VULKAN_1_0;
    case TargetEnv::vulkan1_1: return SPV_ENV_VULKAN_1_1;
    case TargetEnv::vulkan1_2: return SPV_ENV_VULKAN_1_2;
    case TargetEnv::vulkan1_3: return SPV_ENV_VULKAN_1_3;
  }
  return SPV_ENV_VULKAN_1_2;
}

// Collects SPIRV-Tools messages into one line each.
struct MessageLog {
  std::string text;
  spvtools::MessageConsumer consumer() {
    return [this](spv_message_level_t level, const char*, const spv_position_t& position, const char* message) {
      if (level > SPV_MSG_WARNING) return;
      if (!text.empty()) text += "; ";
      text += message;
      if (position.index) text += " (word " + std::to_string(position.index) + ")";
    };
  }
};

// Friendly names (`%color` instead of `%42` in messages) cost a walk over the whole module
// before validating it, about a third of the validator's time on a small shader; only a
// failure's message needs them, so a failure is validated a second time with them.
bool passes_validation(std::span<const std::uint32_t> words, TargetEnv env, MessageLog* log) {
  spvtools::SpirvTools tools(environment(env));
  if (log) tools.SetMessageConsumer(log->consumer());
  spvtools::ValidatorOptions options;
  options.SetFriendlyNames(log != nullptr);
  return tools.Validate(words.data(), words.size(), options);
}

}  // namespace

Status validate_spirv(std::span<const std::uint32_t> words, TargetEnv env) {
  if (passes_validation(words, env, nullptr)) return Ok{};
  MessageLog log;
  passes_validation(words, env, &log);
  return make_error("SPIR-V validation failed: " + (log.text.empty() ? std::string("no message") : log.text));
}

Result<OptimisedBlob> optimise_and_validate(std::vector<std::uint32_t> words, TargetEnv env) {
  if (Status valid = validate_spirv(words, env); !valid) return std::move(valid).take_errors();
  spvtools::Optimizer optimizer(environment(env));
  MessageLog log;
  optimizer.SetMessageConsumer(log.consumer());
  optimizer.RegisterPerformancePasses();
  OptimisedBlob out;
  std::vector<std::uint32_t> optimised;
  spvtools::OptimizerOptions options;
  options.set_run_validator(false);  // validated just above and just below
  if (!optimizer.Run(words.data(), words.size(), &optimised, options)) {
    out.words = std::move(words);
    out.fell_back = true;
    out.fallback_reason = "optimiser failed: " + log.text;
    return out;
  }
  if (Status valid = validate_spirv(optimised, env); !valid) {
    out.words = std::move(words);
    out.fell_back = true;
    out.fallback_reason = "optimised blob is invalid: " + valid.errors().front().message;
    return out;
  }
  out.words = std::move(optimised);
  return out;
}

Result<std::vector<std::uint32_t>> strip_debug_info(std::span<const std::uint32_t> words, TargetEnv env) {
  spvtools::Optimizer optimizer(environment(env));
  MessageLog log;
  optimizer.SetMessageConsumer(log.consumer());
  optimizer.RegisterPass(spvtools::CreateStripDebugInfoPass());
  std::vector<std::uint32_t> stripped;
  spvtools::OptimizerOptions options;
  options.set_run_validator(false);  // removing debug instructions cannot make a valid blob invalid
  if (!optimizer.Run(words.data(), words.size(), &stripped, options))
    return make_error("stripping debug information failed: " + log.text);
  return stripped;
}

}  // namespace shadergen
