#include "pipelines.h"

#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <shadergen/registry.h>

#include <array>
#include <cstddef>
#include <cstring>
#include <string>

namespace tilelight {
namespace {

// shadergen::vk casts the registry's kinds to VkDescriptorType for every layout the runtime
// builds from reflection: they must be the same numbers.
using shadergen::DescriptorKind;
constexpr bool same_kind(DescriptorKind kind, VkDescriptorType type) {
  return static_cast<std::uint32_t>(kind) == static_cast<std::uint32_t>(type);
}
static_assert(same_kind(DescriptorKind::sampler, VK_DESCRIPTOR_TYPE_SAMPLER));
static_assert(same_kind(DescriptorKind::combined_image_sampler, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER));
static_assert(same_kind(DescriptorKind::sampled_image, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE));
static_assert(same_kind(DescriptorKind::storage_image, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE));
static_assert(same_kind(DescriptorKind::uniform_texel_buffer, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER));
static_assert(same_kind(DescriptorKind::storage_texel_buffer, VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER));
static_assert(same_kind(DescriptorKind::uniform_buffer, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER));
static_assert(same_kind(DescriptorKind::storage_buffer, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER));
static_assert(same_kind(DescriptorKind::input_attachment, VK_DESCRIPTOR_TYPE_INPUT_ATTACHMENT));
static_assert(same_kind(DescriptorKind::acceleration_structure, VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR));

}  // namespace

UniqueShaderModule create_shader_module(const Context& context, std::span<const std::uint32_t> spirv,
                                        std::string_view name) {
  if (spirv.empty()) throw Error("shader '" + std::string(name) + "' has no SPIR-V");
  VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  info.codeSize = spirv.size_bytes();
  info.pCode = spirv.data();
  VkShaderModule module = VK_NULL_HANDLE;
  check(vkCreateShaderModule(context.device(), &info, nullptr, &module), "vkCreateShaderModule", name);
  UniqueShaderModule owned(module, {context.device()});
  context.name_object(module, name);
  return owned;
}

UniqueDescriptorSetLayout create_descriptor_set_layout(const Context& context,
                                                       std::span<const VkDescriptorSetLayoutBinding> bindings,
                                                       std::string_view name) {
  VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  info.bindingCount = static_cast<std::uint32_t>(bindings.size());
  info.pBindings = bindings.data();
  VkDescriptorSetLayout layout = VK_NULL_HANDLE;
  check(vkCreateDescriptorSetLayout(context.device(), &info, nullptr, &layout), "vkCreateDescriptorSetLayout", name);
  UniqueDescriptorSetLayout owned(layout, {context.device()});
  context.name_object(layout, name);
  return owned;
}

UniquePipelineLayout create_pipeline_layout(const Context& context, std::span<const VkDescriptorSetLayout> set_layouts,
                                            std::span<const VkPushConstantRange> push_constants,
                                            std::string_view name) {
  VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  info.setLayoutCount = static_cast<std::uint32_t>(set_layouts.size());
  info.pSetLayouts = set_layouts.data();
  info.pushConstantRangeCount = static_cast<std::uint32_t>(push_constants.size());
  info.pPushConstantRanges = push_constants.data();
  VkPipelineLayout layout = VK_NULL_HANDLE;
  check(vkCreatePipelineLayout(context.device(), &info, nullptr, &layout), "vkCreatePipelineLayout", name);
  UniquePipelineLayout owned(layout, {context.device()});
  context.name_object(layout, name);
  return owned;
}

SpecConstants& SpecConstants::set(std::uint32_t constant_id, std::uint32_t value) {
  const auto offset = static_cast<std::uint32_t>(values_.size() * sizeof(std::uint32_t));
  entries_.push_back({constant_id, offset, sizeof(std::uint32_t)});
  values_.push_back(value);
  return *this;
}

SpecConstants& SpecConstants::add(const VkSpecializationInfo& info) {
  for (std::uint32_t i = 0; i < info.mapEntryCount; ++i) {
    const VkSpecializationMapEntry& entry = info.pMapEntries[i];
    if (entry.size != sizeof(std::uint32_t) || entry.offset + entry.size > info.dataSize) {
      throw Error("specialization constant " + std::to_string(entry.constantID) + ": not a 4-byte value in the data");
    }
    std::uint32_t value = 0;
    std::memcpy(&value, static_cast<const std::byte*>(info.pData) + entry.offset, sizeof(value));
    set(entry.constantID, value);
  }
  return *this;
}

const VkSpecializationInfo* SpecConstants::info() {
  if (entries_.empty()) return nullptr;
  info_.mapEntryCount = static_cast<std::uint32_t>(entries_.size());
  info_.pMapEntries = entries_.data();
  info_.dataSize = values_.size() * sizeof(std::uint32_t);
  info_.pData = values_.data();
  return &info_;
}

UniquePipeline create_compute_pipeline(const Context& context, VkPipelineLayout layout,
                                       std::span<const std::uint32_t> spirv, SpecConstants spec,
                                       std::string_view name) {
  const UniqueShaderModule module = create_shader_module(context, spirv, name);
  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = module.get();
  info.stage.pName = "main";
  info.stage.pSpecializationInfo = spec.info();
  info.layout = layout;
  VkPipeline pipeline = VK_NULL_HANDLE;
  check(vkCreateComputePipelines(context.device(), context.pipeline_cache(), 1, &info, nullptr, &pipeline),
        "vkCreateComputePipelines", name);
  UniquePipeline owned(pipeline, {context.device()});
  context.name_object(pipeline, name);
  return owned;
}

namespace {

VkPipelineShaderStageCreateInfo stage_info(VkShaderStageFlagBits stage, VkShaderModule module,
                                           const VkSpecializationInfo* constants) {
  return {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, stage, module, "main", constants};
}

// The vertex and (optional) fragment stage of a graphics pipeline, with the modules and the
// specialization data their create infos point into: neither copied nor moved.
class GraphicsStages {
 public:
  GraphicsStages(const Context& context, const GraphicsPipelineDesc& desc)
      : vertex_(create_shader_module(context, desc.vertex_spirv, desc.name + " (vertex)")),
        fragment_constants_(desc.fragment_constants) {
    stages_[0] = stage_info(VK_SHADER_STAGE_VERTEX_BIT, vertex_.get(), nullptr);
    if (!desc.fragment_spirv.empty()) {
      fragment_ = create_shader_module(context, desc.fragment_spirv, desc.name + " (fragment)");
      stages_[1] = stage_info(VK_SHADER_STAGE_FRAGMENT_BIT, fragment_.get(), fragment_constants_.info());
      count_ = 2;
    }
  }
  GraphicsStages(const GraphicsStages&) = delete;
  GraphicsStages& operator=(const GraphicsStages&) = delete;

  std::uint32_t count() const { return count_; }
  const VkPipelineShaderStageCreateInfo* data() const { return stages_.data(); }

 private:
  UniqueShaderModule vertex_, fragment_;
  SpecConstants fragment_constants_;
  std::array<VkPipelineShaderStageCreateInfo, 2> stages_{};
  std::uint32_t count_ = 1;
};

// Points into desc's binding and attribute vectors.
VkPipelineVertexInputStateCreateInfo vertex_input_state(const GraphicsPipelineDesc& desc) {
  VkPipelineVertexInputStateCreateInfo input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  input.vertexBindingDescriptionCount = static_cast<std::uint32_t>(desc.vertex_bindings.size());
  input.pVertexBindingDescriptions = desc.vertex_bindings.data();
  input.vertexAttributeDescriptionCount = static_cast<std::uint32_t>(desc.vertex_attributes.size());
  input.pVertexAttributeDescriptions = desc.vertex_attributes.data();
  return input;
}

// Filled triangles, desc's culling (none by default: thin geometry is seen from both sides) and
// depth bias.
VkPipelineRasterizationStateCreateInfo rasterization_state(const GraphicsPipelineDesc& desc) {
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.depthClampEnable = desc.depth_clamp ? VK_TRUE : VK_FALSE;
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = desc.cull_mode;
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  raster.lineWidth = 1.0f;
  raster.depthBiasEnable = desc.depth_bias ? VK_TRUE : VK_FALSE;
  raster.depthBiasConstantFactor = desc.depth_bias ? desc.depth_bias->constant : 0.0f;
  raster.depthBiasSlopeFactor = desc.depth_bias ? desc.depth_bias->slope : 0.0f;
  return raster;
}

VkPipelineDepthStencilStateCreateInfo depth_state(const GraphicsPipelineDesc& desc) {
  VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = desc.depth_test ? VK_TRUE : VK_FALSE;
  depth.depthWriteEnable = desc.depth_write ? VK_TRUE : VK_FALSE;
  depth.depthCompareOp = desc.depth_compare;
  if (desc.stencil) {
    depth.stencilTestEnable = VK_TRUE;
    depth.front = depth.back = *desc.stencil;
  }
  return depth;
}

// Every colour attachment written whole: replaced, or with `additive` added to (ONE, ONE); with
// `write` false, not at all.
std::vector<VkPipelineColorBlendAttachmentState> blend_attachments(std::uint32_t count, bool additive, bool alpha,
                                                                   bool write) {
  std::vector<VkPipelineColorBlendAttachmentState> blend(count);
  for (VkPipelineColorBlendAttachmentState& b : blend) {
    if (!write) continue;  // no write mask: the attachment keeps its contents
    b.colorWriteMask =
        VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    if (alpha) {
      b.blendEnable = VK_TRUE;
      b.srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
      b.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
      b.srcAlphaBlendFactor = VK_BLEND_FACTOR_ZERO;
      b.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
      b.colorBlendOp = b.alphaBlendOp = VK_BLEND_OP_ADD;
      continue;
    }
    if (!additive) continue;
    b.blendEnable = VK_TRUE;
    b.srcColorBlendFactor = b.dstColorBlendFactor = VK_BLEND_FACTOR_ONE;
    b.srcAlphaBlendFactor = b.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
    b.colorBlendOp = b.alphaBlendOp = VK_BLEND_OP_ADD;
  }
  return blend;
}

}  // namespace

UniquePipeline create_graphics_pipeline(const Context& context, const GraphicsPipelineDesc& desc) {
  const GraphicsStages stages(context, desc);
  const VkPipelineVertexInputStateCreateInfo vertex_input = vertex_input_state(desc);
  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = desc.topology;
  // Viewport and scissor are dynamic (set_viewport_and_scissor()): one pipeline serves any size.
  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;
  const std::array<VkDynamicState, 2> dynamic_states{VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dynamic.dynamicStateCount = static_cast<std::uint32_t>(dynamic_states.size());
  dynamic.pDynamicStates = dynamic_states.data();
  const VkPipelineRasterizationStateCreateInfo raster = rasterization_state(desc);
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = desc.samples;
  const VkPipelineDepthStencilStateCreateInfo depth = depth_state(desc);
  const std::vector<VkPipelineColorBlendAttachmentState> blend =
      blend_attachments(desc.color_attachments, desc.additive_blend, desc.alpha_blend, desc.color_write);
  VkPipelineColorBlendStateCreateInfo color_blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  color_blend.attachmentCount = desc.color_attachments;
  color_blend.pAttachments = blend.data();

  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  info.stageCount = stages.count();
  info.pStages = stages.data();
  info.pVertexInputState = &vertex_input;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth;
  info.pColorBlendState = &color_blend;
  info.pDynamicState = &dynamic;
  info.layout = desc.layout;
  info.renderPass = desc.render_pass;
  VkPipeline pipeline = VK_NULL_HANDLE;
  check(vkCreateGraphicsPipelines(context.device(), context.pipeline_cache(), 1, &info, nullptr, &pipeline),
        "vkCreateGraphicsPipelines", desc.name);
  UniquePipeline owned(pipeline, {context.device()});
  context.name_object(pipeline, desc.name);
  return owned;
}

GraphicsPipelineDesc depth_from_gbuffer_desc(VkPipelineLayout layout, VkRenderPass render_pass,
                                             std::span<const std::uint32_t> full_screen_vertex,
                                             std::span<const std::uint32_t> fragment, std::string name) {
  GraphicsPipelineDesc desc;
  desc.layout = layout;
  desc.render_pass = render_pass;
  desc.vertex_spirv = full_screen_vertex;
  desc.fragment_spirv = fragment;
  desc.color_write = false;
  desc.depth_test = true;
  desc.depth_write = true;
  desc.depth_compare = VK_COMPARE_OP_ALWAYS;
  desc.name = std::move(name);
  return desc;
}

void set_viewport_and_scissor(VkCommandBuffer cmd, VkExtent2D extent) {
  const VkViewport viewport{0.0f, 0.0f, static_cast<float>(extent.width), static_cast<float>(extent.height),
                            0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, extent};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
}

}  // namespace tilelight
