#include "reflection.h"

#include <spirv_cross/spirv_cross.hpp>

#include <algorithm>

namespace shadergen {
namespace {

std::uint32_t array_count(const spirv_cross::SPIRType& type) {
    std::uint32_t count = 1;
    for (std::uint32_t size : type.array) count *= std::max(size, 1u);
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
        binding.count = array_count(type);
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
    std::sort(out.begin(), out.end(), [](const VariableInfo& a, const VariableInfo& b) { return a.location < b.location; });
    return out;
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
    std::sort(info.bindings.begin(), info.bindings.end(), [](const BindingInfo& a, const BindingInfo& b) {
        return std::tie(a.set, a.binding) < std::tie(b.set, b.binding);
    });
    for (const spirv_cross::Resource& block : resources.push_constant_buffers)
        info.push_constant_size = static_cast<std::uint32_t>(
            compiler.get_declared_struct_size(compiler.get_type(block.base_type_id)));
    info.inputs = interface_variables(compiler, resources.stage_inputs);
    info.outputs = interface_variables(compiler, resources.stage_outputs);
    if (stage == Stage::compute)
        for (std::uint32_t axis = 0; axis < 3; ++axis)
            info.local_size[axis] = compiler.get_execution_mode_argument(spv::ExecutionModeLocalSize, axis);
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
