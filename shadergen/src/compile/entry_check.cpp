#include "compile/entry_check.h"

#include <optional>

#include "compile/spirv_passes.h"

namespace shadergen {
namespace {

constexpr std::uint32_t kOpEntryPoint = 15;
constexpr std::size_t kHeaderWords = 5;

// SPIR-V's ExecutionModel of each stage.
std::optional<std::uint32_t> execution_model(Stage stage) {
  switch (stage) {
    case Stage::vertex: return 0;
    case Stage::tess_control: return 1;
    case Stage::tess_evaluation: return 2;
    case Stage::geometry: return 3;
    case Stage::fragment: return 4;
    case Stage::compute: return 5;
    case Stage::task: return 5364;
    case Stage::mesh: return 5365;
    case Stage::ray_generation: return 5313;
    case Stage::intersection: return 5314;
    case Stage::any_hit: return 5315;
    case Stage::closest_hit: return 5316;
    case Stage::miss: return 5317;
    case Stage::callable: return 5318;
  }
  return std::nullopt;
}

// True when some OpEntryPoint has `model`. A signed entry's words reach it unvalidated (though
// signed by a writer that validated them), so every instruction's bounds are checked.
bool has_entry_point(std::span<const std::uint32_t> words, std::uint32_t model) {
  for (std::size_t at = kHeaderWords; at < words.size();) {
    std::uint32_t count = words[at] >> 16, opcode = words[at] & 0xFFFFu;
    if (count == 0 || at + count > words.size()) return false;
    if (opcode == kOpEntryPoint && count > 1 && words[at + 1] == model) return true;
    at += count;
  }
  return false;
}

}  // namespace

std::string unfit_reason(std::span<const std::uint32_t> words, Stage stage, TargetEnv env) {
  if (Status valid = validate_spirv(words, env); !valid) return valid.errors().front().message;
  return wrong_stage_reason(words, stage);
}

std::string wrong_stage_reason(std::span<const std::uint32_t> words, Stage stage) {
  auto model = execution_model(stage);
  if (model && !has_entry_point(words, *model)) return "no entry point of the expected stage";
  return {};
}

}  // namespace shadergen
