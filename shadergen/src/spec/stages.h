// stages.h - the shader stages shadergen compiles, by the names a spec may use for them.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "shadergen/registry.h"

namespace shadergen {

// A stage by its name ("fragment") or short name ("frag"); nullopt for anything else.
std::optional<Stage> parse_stage(std::string_view name);

// The stage a file's extension names (".frag" -> fragment, ".rchit" -> closest_hit, and
// "shade.frag.glsl" -> fragment as glslangValidator reads it); nullopt when it names none
// ("shade.glsl").
std::optional<Stage> stage_for_extension(const std::filesystem::path& file);

// "vertex, tess_control, ..." and ".vert .tesc ...", for messages.
std::string stage_names();
std::string stage_extensions();

// Stages that have a work-group size: compute, task and mesh.
bool has_workgroup(Stage stage);

}  // namespace shadergen
