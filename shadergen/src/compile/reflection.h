// reflection.h - what a blob needs from a pipeline layout, read back with SPIRV-Cross.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "shadergen/diagnostic.h"
#include "shadergen/registry.h"

namespace shadergen {

struct BindingInfo {
  std::uint32_t set = 0;
  std::uint32_t binding = 0;
  DescriptorKind kind = DescriptorKind::uniform_buffer;
  std::uint32_t count = 1;   // 0 when runtime-sized
  std::uint32_t stages = 0;  // VkShaderStageFlags-compatible
  std::string name;
  bool runtime_sized = false;
  std::uint32_t input_attachment_index = 0;
  bool operator==(const BindingInfo&) const = default;
};

struct VariableInfo {
  std::uint32_t location = 0;
  std::uint32_t components = 0;
  std::string name;
  bool operator==(const VariableInfo&) const = default;
};

struct SpecConstantInfo {
  std::uint32_t id = 0;  // constant_id
  std::string name;
  ScalarType type = ScalarType::uint32;
  std::uint32_t default_bits = 0;
  bool operator==(const SpecConstantInfo&) const = default;
};

struct ReflectionInfo {
  std::vector<BindingInfo> bindings;  // sorted by (set, binding)
  std::uint32_t push_constant_size = 0;
  std::vector<VariableInfo> inputs;  // sorted by location; built-ins excluded
  std::vector<VariableInfo> outputs;
  std::array<std::uint32_t, 3> local_size{0, 0, 0};
  std::array<std::uint32_t, 3> local_size_ids{Reflection::kNoConstant, Reflection::kNoConstant,
                                              Reflection::kNoConstant};
  std::vector<SpecConstantInfo> specialization_constants;  // sorted by id
  bool operator==(const ReflectionInfo&) const = default;
};

// Reflects only the resources the entry point statically uses, so an optimised permutation
// that dropped a feature also drops its bindings. Precondition: `words` is valid SPIR-V.
Result<ReflectionInfo> reflect(std::span<const std::uint32_t> words, Stage stage);

}  // namespace shadergen
