#include "spec/stages.h"

#include <array>

#include "shadergen/domain.h"

namespace shadergen {
namespace {

struct StageInfo {
  Stage stage;
  std::string_view name;       // as in the spec, the manifest and the C++ enum
  std::string_view extension;  // the file extension and glslangValidator's -S name
};

constexpr std::array<StageInfo, 14> kStages{{
    {Stage::vertex, "vertex", "vert"},
    {Stage::tess_control, "tess_control", "tesc"},
    {Stage::tess_evaluation, "tess_evaluation", "tese"},
    {Stage::geometry, "geometry", "geom"},
    {Stage::fragment, "fragment", "frag"},
    {Stage::compute, "compute", "comp"},
    {Stage::task, "task", "task"},
    {Stage::mesh, "mesh", "mesh"},
    {Stage::ray_generation, "ray_generation", "rgen"},
    {Stage::any_hit, "any_hit", "rahit"},
    {Stage::closest_hit, "closest_hit", "rchit"},
    {Stage::miss, "miss", "rmiss"},
    {Stage::intersection, "intersection", "rint"},
    {Stage::callable, "callable", "rcall"},
}};

const StageInfo* find(Stage stage) {
  for (const StageInfo& info : kStages)
    if (info.stage == stage) return &info;
  return nullptr;
}

}  // namespace

std::string_view stage_name(Stage stage) {
  const StageInfo* info = find(stage);
  return info ? info->name : "?";
}

std::string_view stage_extension(Stage stage) {
  const StageInfo* info = find(stage);
  return info ? info->extension : "?";
}

std::optional<Stage> parse_stage(std::string_view name) {
  for (const StageInfo& info : kStages)
    if (info.name == name || info.extension == name) return info.stage;
  return std::nullopt;
}

std::optional<Stage> stage_for_extension(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  // glslangValidator's other convention: `name.<stage>.glsl` (shade.frag.glsl).
  if (extension == ".glsl") extension = file.stem().extension().string();
  if (extension.size() < 2) return std::nullopt;
  for (const StageInfo& info : kStages)
    if (info.extension == std::string_view(extension).substr(1)) return info.stage;
  return std::nullopt;
}

std::string stage_names() {
  std::string text;
  for (const StageInfo& info : kStages) text += (text.empty() ? "" : ", ") + std::string(info.name);
  return text;
}

std::string stage_extensions() {
  std::string text;
  for (const StageInfo& info : kStages) text += (text.empty() ? "." : " .") + std::string(info.extension);
  return text;
}

bool has_workgroup(Stage stage) { return stage == Stage::compute || stage == Stage::task || stage == Stage::mesh; }

}  // namespace shadergen
