#include "reflection.h"

#include <spirv_cross/spirv_cross.hpp>

#include <algorithm>

#include "stages.h"

namespace shadergen {
namespace {

// The element count of a binding's array type: the product of its dimensions, a dimension
// sized by a specialization constant counting as that constant's default, 0 when one is
// runtime-sized (`t[]`).
std::uint32_t array_count(const spirv_cross::Compiler& compiler, const spirv_cross::SPIRType& type) {
  std::uint32_t count = 1;
  for (std::size_t i = 0; i < type.array.size(); ++i) {
    bool literal = i >= type.array_size_literal.size() || type.array_size_literal[i];
    std::uint32_t size = literal ? type.array[i] : compiler.get_constant(type.array[i]).scalar();
    if (literal && size == 0) return 0;
    count *= size;
  }
  return count;
}

void add_bindings(const spirv_cross::Compiler& compiler, const spirv_cross::SmallVector<spirv_cross::Resource>& list,
                  DescriptorKind kind, DescriptorKind texel_kind, Stage stage, std::vector<BindingInfo>& out) {
  for (const spirv_cross::Resource& resource : list) {
    const spirv_cross::SPIRType& type = compiler.get_type(resource.type_id);
    bool texel_buffer = type.basetype == spirv_cross::SPIRType::Image && type.image.dim == spv::DimBuffer;
    BindingInfo binding;
    binding.set = compiler.get_decoration(resource.id, spv::DecorationDescriptorSet);
    binding.binding = compiler.get_decoration(resource.id, spv::DecorationBinding);
    binding.kind = texel_buffer ? texel_kind : kind;
    binding.count = array_count(compiler, type);
    binding.runtime_sized = binding.count == 0;
    if (kind == DescriptorKind::input_attachment)
      binding.input_attachment_index = compiler.get_decoration(resource.id, spv::DecorationInputAttachmentIndex);
    binding.stages = static_cast<std::uint32_t>(stage);
    binding.name = resource.name;
    out.push_back(std::move(binding));
  }
}

std::vector<VariableInfo> interface_variables(const spirv_cross::Compiler& compiler,
                                              const spirv_cross::SmallVector<spirv_cross::Resource>& list) {
  std::vector<VariableInfo> out;
  for (const spirv_cross::Resource& resource : list) {
    const spirv_cross::SPIRType& type = compiler.get_type(resource.type_id);
    out.push_back({compiler.get_decoration(resource.id, spv::DecorationLocation), type.vecsize, resource.name});
  }
  std::sort(out.begin(), out.end(),
            [](const VariableInfo& a, const VariableInfo& b) { return a.location < b.location; });
  return out;
}

ScalarType scalar_type(const spirv_cross::SPIRType& type) {
  switch (type.basetype) {
    case spirv_cross::SPIRType::Boolean: return ScalarType::boolean;
    case spirv_cross::SPIRType::Int: return ScalarType::int32;
    case spirv_cross::SPIRType::Float: return ScalarType::float32;
    default: return ScalarType::uint32;
  }
}

std::vector<SpecConstantInfo> specialization_constants(const spirv_cross::Compiler& compiler) {
  std::vector<SpecConstantInfo> out;
  for (const spirv_cross::SpecializationConstant& c : compiler.get_specialization_constants()) {
    const spirv_cross::SPIRConstant& constant = compiler.get_constant(c.id);
    const spirv_cross::SPIRType& type = compiler.get_type(constant.constant_type);
    // The work-group size composite (gl_WorkGroupSize) is no constant of its own.
    if (type.vecsize != 1 || type.columns != 1) continue;
    out.push_back({c.constant_id, compiler.get_name(c.id), scalar_type(type), constant.scalar()});
  }
  // glslang may declare one constant_id twice (a work-group axis and the named constant);
  // a pipeline sets it once, so it is listed once, named where a declaration names it.
  std::stable_sort(out.begin(), out.end(), [](const SpecConstantInfo& a, const SpecConstantInfo& b) {
    return a.id != b.id ? a.id < b.id : !a.name.empty() && b.name.empty();
  });
  out.erase(std::unique(out.begin(), out.end(),
                        [](const SpecConstantInfo& a, const SpecConstantInfo& b) { return a.id == b.id; }),
            out.end());
  return out;
}

// The work-group size: each axis a literal, or a specialization constant (local_size_x_id)
// whose default the size reports and whose constant_id local_size_ids records.
void workgroup(const spirv_cross::Compiler& compiler, ReflectionInfo& info) {
  spirv_cross::SpecializationConstant axes[3];
  compiler.get_work_group_size_specialization_constants(axes[0], axes[1], axes[2]);
  bool by_id = compiler.get_execution_mode_bitset().get(spv::ExecutionModeLocalSizeId);
  for (std::uint32_t axis = 0; axis < 3; ++axis) {
    if (axes[axis].id) {
      info.local_size_ids[axis] = axes[axis].constant_id;
      info.local_size[axis] = compiler.get_constant(axes[axis].id).scalar();
    } else if (by_id) {
      std::uint32_t id = compiler.get_execution_mode_argument(spv::ExecutionModeLocalSizeId, axis);
      info.local_size[axis] = compiler.get_constant(id).scalar();
    } else {
      info.local_size[axis] = compiler.get_execution_mode_argument(spv::ExecutionModeLocalSize, axis);
    }
  }
}

ReflectionInfo reflect_unchecked(std::span<const std::uint32_t> words, Stage stage) {
  spirv_cross::Compiler compiler(words.data(), words.size());
  auto active = compiler.get_active_interface_variables();
  spirv_cross::ShaderResources resources = compiler.get_shader_resources(active);
  ReflectionInfo info;
  using K = DescriptorKind;
  add_bindings(compiler, resources.uniform_buffers, K::uniform_buffer, K::uniform_buffer, stage, info.bindings);
  add_bindings(compiler, resources.storage_buffers, K::storage_buffer, K::storage_buffer, stage, info.bindings);
  add_bindings(compiler, resources.sampled_images, K::combined_image_sampler, K::uniform_texel_buffer, stage,
               info.bindings);
  add_bindings(compiler, resources.separate_images, K::sampled_image, K::uniform_texel_buffer, stage, info.bindings);
  add_bindings(compiler, resources.separate_samplers, K::sampler, K::sampler, stage, info.bindings);
  add_bindings(compiler, resources.storage_images, K::storage_image, K::storage_texel_buffer, stage, info.bindings);
  add_bindings(compiler, resources.subpass_inputs, K::input_attachment, K::input_attachment, stage, info.bindings);
  add_bindings(compiler, resources.acceleration_structures, K::acceleration_structure, K::acceleration_structure, stage,
               info.bindings);
  std::sort(info.bindings.begin(), info.bindings.end(), [](const BindingInfo& a, const BindingInfo& b) {
    return std::tie(a.set, a.binding) < std::tie(b.set, b.binding);
  });
  for (const spirv_cross::Resource& block : resources.push_constant_buffers)
    info.push_constant_size =
        static_cast<std::uint32_t>(compiler.get_declared_struct_size(compiler.get_type(block.base_type_id)));
  info.inputs = interface_variables(compiler, resources.stage_inputs);
  info.outputs = interface_variables(compiler, resources.stage_outputs);
  info.specialization_constants = specialization_constants(compiler);
  if (has_workgroup(stage)) workgroup(compiler, info);
  return info;
}

}  // namespace

Result<ReflectionInfo> reflect(std::span<const std::uint32_t> words, Stage stage) {
  try {
    return reflect_unchecked(words, stage);
  } catch (const std::exception& error) {
    // SPIRV-Cross reports unsupported constructs by throwing.
    return make_error(std::string("SPIRV-Cross reflection failed: ") + error.what());
  }
}

}  // namespace shadergen
