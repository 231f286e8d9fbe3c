#include "compile/reflection.h"

#include <spirv_cross/spirv_cross.hpp>

#include <algorithm>

#include "compile/layout_check.h"
#include "spec/stages.h"

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
    // `samplerBuffer` is a SampledImage type, `textureBuffer` and `imageBuffer` Image types:
    // with Dim Buffer each is a texel buffer, whatever list SPIRV-Cross files it under.
    bool image_type =
        type.basetype == spirv_cross::SPIRType::Image || type.basetype == spirv_cross::SPIRType::SampledImage;
    bool texel_buffer = image_type && type.image.dim == spv::DimBuffer;
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

// Locations one value of `type` takes: a column per location, times every array dimension
// (`outer_arrays` of them are the per-vertex array of an arrayed interface and take none).
std::uint32_t locations_of(const spirv_cross::SPIRType& type, std::size_t outer_arrays) {
  std::uint32_t count = std::max(type.columns, 1u);
  for (std::size_t i = 0; i + outer_arrays < type.array.size(); ++i) count *= std::max(type.array[i], 1u);
  return count;
}

// A stage whose inputs (or outputs) carry one element per vertex: their outermost array
// dimension is the vertex, not locations.
bool arrayed_interface(Stage stage, bool input) {
  switch (stage) {
    case Stage::tess_control: return true;
    case Stage::tess_evaluation:
    case Stage::geometry: return input;
    case Stage::mesh: return !input;
    default: return false;
  }
}

// An interface block's members, each at the locations it really takes: its own Location, or
// the one after the previous member's.
void block_members(const spirv_cross::Compiler& compiler, const spirv_cross::Resource& resource, std::uint32_t location,
                   std::vector<VariableInfo>& out) {
  const spirv_cross::SPIRType& block = compiler.get_type(resource.base_type_id);
  for (std::uint32_t m = 0; m < block.member_types.size(); ++m) {
    const spirv_cross::SPIRType& member = compiler.get_type(block.member_types[m]);
    if (compiler.has_member_decoration(block.self, m, spv::DecorationLocation))
      location = compiler.get_member_decoration(block.self, m, spv::DecorationLocation);
    std::string name = resource.name + "." + compiler.get_member_name(block.self, m);
    for (std::uint32_t i = 0; i < locations_of(member, 0); ++i) out.push_back({location++, member.vecsize, name});
  }
}

// Only variables with a Location take part: built-ins are listed apart by SPIRV-Cross, and an
// NV task block (`taskNV out Task {...}`) has none, being no attachment or varying.
std::vector<VariableInfo> interface_variables(const spirv_cross::Compiler& compiler,
                                              const spirv_cross::SmallVector<spirv_cross::Resource>& list, Stage stage,
                                              bool input) {
  std::vector<VariableInfo> out;
  for (const spirv_cross::Resource& resource : list) {
    const spirv_cross::SPIRType& type = compiler.get_type(resource.type_id);
    bool has_location = compiler.has_decoration(resource.id, spv::DecorationLocation);
    std::uint32_t location = compiler.get_decoration(resource.id, spv::DecorationLocation);
    if (type.basetype == spirv_cross::SPIRType::Struct) {
      const spirv_cross::SPIRType& block = compiler.get_type(resource.base_type_id);
      bool members_placed =
          !block.member_types.empty() && compiler.has_member_decoration(block.self, 0, spv::DecorationLocation);
      if (has_location || members_placed) block_members(compiler, resource, location, out);
      continue;
    }
    if (!has_location) continue;
    std::uint32_t taken = locations_of(type, arrayed_interface(stage, input) && !type.array.empty() ? 1 : 0);
    for (std::uint32_t i = 0; i < taken; ++i) out.push_back({location + i, type.vecsize, resource.name});
  }
  std::stable_sort(out.begin(), out.end(),
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
  std::stable_sort(info.bindings.begin(), info.bindings.end(), [](const BindingInfo& a, const BindingInfo& b) {
    return std::tie(a.set, a.binding) < std::tie(b.set, b.binding);
  });
  for (const spirv_cross::Resource& block : resources.push_constant_buffers)
    info.push_constant_size =
        static_cast<std::uint32_t>(compiler.get_declared_struct_size(compiler.get_type(block.base_type_id)));
  info.inputs = interface_variables(compiler, resources.stage_inputs, stage, true);
  info.outputs = interface_variables(compiler, resources.stage_outputs, stage, false);
  info.specialization_constants = specialization_constants(compiler);
  if (has_workgroup(stage)) workgroup(compiler, info);
  return info;
}

std::string describe(const BindingInfo& b) {
  return std::string(descriptor_kind_name(b.kind)) +
         (b.count != 1 ? std::string("[").append(std::to_string(b.count)).append("]") : "") + " \"" + b.name + "\"";
}

// Declarations aliased at one (set, binding) are one descriptor: a set layout lists it once,
// under the first declaration's name. Aliases of another kind or count cannot share it.
Result<ReflectionInfo> merge_aliases(ReflectionInfo info) {
  std::vector<BindingInfo> merged;
  Diagnostics errors;
  for (BindingInfo& binding : info.bindings) {
    if (merged.empty() || merged.back().set != binding.set || merged.back().binding != binding.binding) {
      merged.push_back(std::move(binding));
    } else if (merged.back().kind != binding.kind || merged.back().count != binding.count) {
      errors.push_back(make_error("set " + std::to_string(binding.set) + " binding " + std::to_string(binding.binding) +
                                  " is declared as " + describe(merged.back()) + " and as " + describe(binding) +
                                  "; aliased declarations must have one descriptor kind and count"));
    }
  }
  if (!errors.empty()) return errors;
  info.bindings = std::move(merged);
  return info;
}

}  // namespace

Result<ReflectionInfo> reflect(std::span<const std::uint32_t> words, Stage stage) {
  try {
    return merge_aliases(reflect_unchecked(words, stage));
  } catch (const std::exception& error) {
    // SPIRV-Cross reports unsupported constructs by throwing.
    return make_error(std::string("SPIRV-Cross reflection failed: ") + error.what());
  }
}

}  // namespace shadergen
