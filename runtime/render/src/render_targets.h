#pragma once
// The images one frame renders into, with their render passes and framebuffers:
// the multisampled G-buffer (Table 4.1, uber/include/gbuffer.glsl), the sun shadow map and the
// light targets (classified, naive and dynamic), which the frame reads back for comparison and
// the PNGs. The G-buffer has two render passes over the same images: the classified path's,
// which also writes the coverage flags (RT4, with 2 or more samples), and the baselines' plain
// one, which writes what lighting reads and nothing else.

#include "pipelines.h"
#include "tilelight/vulkan/image.h"
#include "tilelight/vulkan/vk_handles.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>

namespace tilelight {

class Context;

inline constexpr VkFormat kGBufferRt0Format = VK_FORMAT_R8G8B8A8_UNORM;
inline constexpr VkFormat kGBufferRt1Format = VK_FORMAT_R16G16B16A16_SFLOAT;
inline constexpr VkFormat kGBufferRt2Format = VK_FORMAT_R16G16B16A16_SFLOAT;
inline constexpr VkFormat kGBufferRt3Format = VK_FORMAT_R32_SFLOAT;  // surface depth + sun bit
inline constexpr VkFormat kGBufferTagFormat = VK_FORMAT_R8_UINT;     // RT4: coverage flags
inline constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;       // the shadow map
// The G-buffer's depth and stencil: D32 with 8 stencil bits where the device has it (with
// multisampling and sampling), else 24-bit depth (gbuffer_depth_format()). The stencil marks the
// pixels that need lighting (§19.7.2): every material writes kStencilLit, the sky leaves 0.
inline constexpr VkFormat kGBufferDepthFormat = VK_FORMAT_D32_SFLOAT_S8_UINT;
inline constexpr VkFormat kGBufferDepthFallbackFormat = VK_FORMAT_D24_UNORM_S8_UINT;
inline constexpr std::uint32_t kStencilLit = 1;

// The stencil state of a G-buffer material: kStencilLit written wherever it passes the depth
// test (no extra draw: the marking rides on the materials' own draws).
VkStencilOpState gbuffer_stencil_marking();
inline constexpr VkFormat kLightFormat = VK_FORMAT_R16G16B16A16_SFLOAT;

class RenderTargets {
 public:
  // Preconditions: the caller checked extent against the device limits and `samples` against
  // the device's G-buffer sample counts.
  // `storage_light_targets`: the light targets are also written by compute (the compute light
  // pass: storage image, cleared by transfer); the device must support storage images of
  // kLightFormat (Image says so when it does not).
  RenderTargets(const Context& context, VkExtent2D extent, VkSampleCountFlagBits samples, std::uint32_t shadow_map_size,
                bool storage_light_targets = false);

  VkExtent2D extent() const { return extent_; }
  VkSampleCountFlagBits samples() const { return samples_; }

  // After the G-buffer pass every G-buffer image is in SHADER_READ_ONLY_OPTIMAL (sampled by
  // classification and lighting), the shadow map likewise, and the light targets are in
  // TRANSFER_SRC_OPTIMAL (read back).
  const Image& rt0() const { return rt0_; }
  const Image& rt1() const { return rt1_; }
  const Image& rt2() const { return rt2_; }
  const Image& rt3() const { return rt3_; }
  // RT4; precondition: has_coverage_flags() (2 or more samples).
  const Image& coverage_flags() const { return flags_; }
  bool has_coverage_flags() const { return samples_ != VK_SAMPLE_COUNT_1_BIT; }
  const Image& shadow_map() const { return shadow_map_; }
  // The G-buffer's depth-stencil format, and a view of its stencil alone, which the passes after
  // the G-buffer sample (SHADER_READ_ONLY_OPTIMAL, like the colour targets).
  VkFormat gbuffer_depth_format() const { return depth_.format(); }
  VkImageView gbuffer_stencil_view() const { return stencil_view_.get(); }
  const Image& classified() const { return classified_; }
  const Image& naive() const { return naive_; }
  const Image& dynamic() const { return dynamic_; }

  // The classified G-buffer's render pass (`with_flags`), or the plain one's; the same with one sample.
  VkRenderPass gbuffer_pass(bool with_flags = true) const {
    return with_flags && has_coverage_flags() ? gbuffer_pass_.get() : plain_gbuffer_pass_.get();
  }
  VkRenderPass shadow_pass() const { return shadow_pass_.get(); }
  VkRenderPass light_pass() const { return light_pass_.get(); }
  VkFramebuffer shadow_framebuffer() const { return shadow_framebuffer_.get(); }
  VkFramebuffer classified_framebuffer() const { return classified_framebuffer_.get(); }
  VkFramebuffer naive_framebuffer() const { return naive_framebuffer_.get(); }
  VkFramebuffer dynamic_framebuffer() const { return dynamic_framebuffer_.get(); }
  VkExtent2D shadow_extent() const { return {shadow_map_size_, shadow_map_size_}; }

  // Begins the classified (`with_flags`) or plain G-buffer render pass (every target cleared; depth
  // to 1) and sets the viewport.
  void begin_gbuffer_pass(VkCommandBuffer cmd, bool with_flags = true) const;

  // What every pipeline writing the G-buffer shares: that render pass and sample count, its
  // colour targets, the depth test, and GBUFFER_SAMPLES (fragment specialization constant 0,
  // see gbuffer.glsl) for the coverage flags. Callers add shaders and depth state.
  GraphicsPipelineDesc gbuffer_pipeline_desc(VkPipelineLayout layout, std::string name, bool with_flags = true) const;
  // The colour attachments of that render pass: RT0..RT3, and RT4 when with_flags.
  std::uint32_t gbuffer_colour_targets(bool with_flags) const { return with_flags && has_coverage_flags() ? 5 : 4; }

 private:
  void create_gbuffer_passes(const Context& context);

  VkExtent2D extent_;
  VkSampleCountFlagBits samples_;
  std::uint32_t shadow_map_size_;
  Image rt0_, rt1_, rt2_, rt3_, flags_, depth_, shadow_map_, classified_, naive_, dynamic_;
  UniqueImageView stencil_view_;
  UniqueRenderPass gbuffer_pass_, plain_gbuffer_pass_, shadow_pass_, light_pass_;
  UniqueFramebuffer gbuffer_framebuffer_, plain_gbuffer_framebuffer_, shadow_framebuffer_, classified_framebuffer_,
      naive_framebuffer_, dynamic_framebuffer_;
};

}  // namespace tilelight
