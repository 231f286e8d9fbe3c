#pragma once
// Samplers. The lighting pass reads the G-buffer with texelFetch (no sampler state needed), so
// samplers here serve the shadow map (depth compare) and any filtered lookups.

#include "tilelight/vulkan/vk_handles.h"

#include <vulkan/vulkan.h>

#include <string>

namespace tilelight {

class Context;

struct SamplerDesc {
  VkFilter filter = VK_FILTER_NEAREST;                                   // both min and mag
  VkSamplerAddressMode address = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;  // u, v and w
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
