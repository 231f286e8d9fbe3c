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
  void attach(spvtools::SpirvTools& tools) {
    tools.SetMessageConsumer([this](spv_message_level_t level, const char*, const spv_position_t& position,
                                    const char* message) { add(level, position, message); });
  }
  void attach(spvtools::Optimizer& optimizer) {
    optimizer.SetMessageConsumer([this](spv_message_level_t level, const char*, const spv_position_t& position,
                                        const char* message) { add(level, position, message); });
  }
  void add(spv_message_level_t level, const spv_position_t& position, const char* message) {
    if (level > SPV_MSG_WARNING) return;
    if (!text.empty()) text += "; ";
    text += message;
    if (position.index) text += " (word " + std::to_string(position.index) + ")";
  }
};

}  // namespace

Status validate_spirv(std::span<const std::uint32_t> words, TargetEnv env) {
  spvtools::SpirvTools tools(environment(env));
  MessageLog log;
  log.attach(tools);
  spvtools::ValidatorOptions options;
  if (!tools.Validate(words.data(), words.size(), options))
    return make_error("SPIR-V validation failed: " + (log.text.empty() ? std::string("no message") : log.text));
  return Ok{};
}

Result<OptimisedBlob> optimise_and_validate(std::vector<std::uint32_t> words, TargetEnv env) {
  if (Status valid = validate_spirv(words, env); !valid) return std::move(valid).take_errors();
  spvtools::Optimizer optimizer(environment(env));
  MessageLog log;
  log.attach(optimizer);
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
  log.attach(optimizer);
  optimizer.RegisterPass(spvtools::CreateStripDebugInfoPass());
  std::vector<std::uint32_t> stripped;
  spvtools::OptimizerOptions options;
  options.set_run_validator(false);  // removing debug instructions cannot make a valid blob invalid
  if (!optimizer.Run(words.data(), words.size(), &stripped, options))
    return make_error("stripping debug information failed: " + log.text);
  return stripped;
}

}  // namespace shadergen
