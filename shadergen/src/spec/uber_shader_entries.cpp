#include "spec/uber_shader_entries.h"

#include <utility>

namespace shadergen {

std::size_t uber_shader_count(const DomainSpec& spec) {
  return spec.uber_shaders.empty() ? 1 : spec.uber_shaders.size();
}

DomainSpec for_uber_shader(const DomainSpec& spec, std::size_t index) {
  DomainSpec entry = spec;
  if (spec.uber_shaders.empty()) return entry;
  const UberShaderEntry& chosen = spec.uber_shaders[index];
  entry.uber = chosen.file;
  entry.entry = chosen.name;
  entry.companions.clear();
  for (const CompanionSpec& companion : spec.companions) {
    const bool mine = companion.uber_shader.empty() ? index == 0 : companion.uber_shader == chosen.name;
    if (mine) entry.companions.push_back(companion);
  }
  return entry;
}

}  // namespace shadergen
