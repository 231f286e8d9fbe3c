#include "companion_shaders.h"

#include "tilelight/error.h"

#include <split_second_shaders.h>

#include <string>

namespace tilelight {

std::span<const std::uint32_t> companion_spirv(std::string_view name) {
  const shadergen::CompanionShader* shader = split_second::registry().companion(name);
  if (shader == nullptr) throw Error("the shader registry has no companion shader '" + std::string(name) + "'");
  return shader->shader.spirv;
}

}  // namespace tilelight
