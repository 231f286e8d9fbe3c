#pragma once
// Shader modules, layouts and pipelines: thin checked wrappers that return RAII handles.

#include "tilelight/vulkan/vk_handles.h"

#include <shadergen/vulkan.h>
#include <vulkan/vulkan.h>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace tilelight {

class Context;

// Precondition: `spirv` is a validated SPIR-V module (shadergen validates every blob).
UniqueShaderModule create_shader_module(const Context& context, std::span<const std::uint32_t> spirv,
                                        std::string_view name);

UniqueDescriptorSetLayout create_descriptor_set_layout(const Context& context,
                                                       std::span<const VkDescriptorSetLayoutBinding> bindings,
                                                       std::string_view name);

UniquePipelineLayout create_pipeline_layout(const Context& context, std::span<const VkDescriptorSetLayout> set_layouts,
                                            std::span<const VkPushConstantRange> push_constants, std::string_view name);

// 32-bit specialization constants, collected by constant ID.
class SpecConstants {
 public:
  SpecConstants& set(std::uint32_t constant_id, std::uint32_t value);
  // Every constant of `info` (4-byte entries, as shadergen::vulkan::specialization_info() makes
  // from a generated N::specialization()): the values of a build's specialization features,
  // beside the runtime's own constants. Throws tilelight::Error for an entry of another size.
  SpecConstants& add(const VkSpecializationInfo& info);
  // Valid until this object changes or dies; nullptr when empty.
  const VkSpecializationInfo* info();

 private:
  std::vector<VkSpecializationMapEntry> entries_;
  std::vector<std::uint32_t> values_;
  VkSpecializationInfo info_{};
};

UniquePipeline create_compute_pipeline(const Context& context, VkPipelineLayout layout,
                                       std::span<const std::uint32_t> spirv, SpecConstants spec, std::string_view name);

// Rasteriser depth bias (vkCmdSetDepthBias's factors, fixed in the pipeline).
struct DepthBias {
  float constant = 0.0f;  // in units of the depth format's minimum resolvable difference
  float slope = 0.0f;     // times the polygon's largest depth slope
};

struct GraphicsPipelineDesc {
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkRenderPass render_pass = VK_NULL_HANDLE;
  std::span<const std::uint32_t> vertex_spirv;
  std::span<const std::uint32_t> fragment_spirv;  // empty: depth-only pipeline
  SpecConstants fragment_constants;               // specialisation of the fragment stage
  std::vector<VkVertexInputBindingDescription> vertex_bindings;
  std::vector<VkVertexInputAttributeDescription> vertex_attributes;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  std::uint32_t color_attachments = 1;
  bool depth_test = false;
  bool depth_write = false;
  VkCompareOp depth_compare = VK_COMPARE_OP_LESS;
  std::optional<DepthBias> depth_bias;  // none: no bias
  // Counter-clockwise triangles face the front (glTF's winding, seen through the y-flipped
  // projection of camera_matrices()); back: single-sided meshes.
  VkCullModeFlags cull_mode = VK_CULL_MODE_NONE;
  VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  // Stencil test and writes, the same for front and back faces; none: no stencil test.
  std::optional<VkStencilOpState> stencil;
  // Fragment depth clamped to the viewport's range instead of primitives clipped at the near and
  // far planes (the device's depthClamp feature: the caller checks it).
  bool depth_clamp = false;
  // false: the colour attachments are left as they are (a pass that writes depth and stencil only).
  bool color_write = true;
  // Colour written as ONE * source + ONE * destination (the local lights add into the light
  // target); otherwise replaced.
  bool additive_blend = false;
  // Colour written as SRC_ALPHA * source + ONE_MINUS_SRC_ALPHA * destination, the destination's
  // alpha kept (the forward pass's blended materials over the light target).
  bool alpha_blend = false;
  std::string name;
};

// A full-screen draw that writes depth and no colour, the depth test ALWAYS: how a pass makes a
// single-sampled depth of its own from the G-buffer (`fragment` writes gl_FragDepth) before it
// draws against it (the local lights' resolve, the forward pass's depth copy).
GraphicsPipelineDesc depth_from_gbuffer_desc(VkPipelineLayout layout, VkRenderPass render_pass,
                                             std::span<const std::uint32_t> full_screen_vertex,
                                             std::span<const std::uint32_t> fragment, std::string name);

// Viewport and scissor are dynamic state: set them when recording.
UniquePipeline create_graphics_pipeline(const Context& context, const GraphicsPipelineDesc& desc);

// Full-framebuffer viewport and scissor.
void set_viewport_and_scissor(VkCommandBuffer cmd, VkExtent2D extent);

}  // namespace tilelight
