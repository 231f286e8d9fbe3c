#pragma once
// Samplers. The lighting pass reads the G-buffer with texelFetch (no sampler state needed), so
// samplers here serve the shadow map (depth compare) and the scene's base colour textures.

#include "tilelight/vulkan/vk_handles.h"

#include <vulkan/vulkan.h>

#include <string>

namespace tilelight {

class Context;

struct SamplerDesc {
  VkFilter mag_filter = VK_FILTER_NEAREST;
  VkFilter min_filter = VK_FILTER_NEAREST;
  VkSamplerMipmapMode mipmap_mode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  // The last mip level read: 0 reads the first level only (the render targets have one);
  // VK_LOD_CLAMP_NONE every level the image has.
  float max_lod = 0.0f;
  VkSamplerAddressMode address_u = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  VkSamplerAddressMode address_v = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;  // w: as u
  // Depth comparison (sampler2DShadow): the result is the fraction of taps that pass.
  bool compare = false;
  VkCompareOp compare_op = VK_COMPARE_OP_LESS_OR_EQUAL;
  // Used with CLAMP_TO_BORDER; opaque white = "lit" outside a shadow map.
  VkBorderColor border = VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE;
  std::string name;
};

class Sampler {
 public:
  Sampler() = default;
  Sampler(const Context& context, SamplerDesc desc);  // throws tilelight::Error

  VkSampler handle() const { return sampler_.get(); }
  const std::string& name() const { return name_; }

 private:
  std::string name_;
  UniqueSampler sampler_;
};

}  // namespace tilelight
