#pragma once
// The pipeline layout of a pass that shades into a light target with the scene's local lights
// (the local-light passes, the forward pass for blended materials), from its domain's merged
// reflection. Both passes share one shape:
//   set 0  as reflected: the lighting parameters, the G-buffer images, what else the pass reads;
//   set 1  the lights: one storage buffer (LocalLightBlock each);
//   set 2  one scene texture (a globe map, a base colour), bound with the scene textures' own
//          set, so its layout must be that one's;
//   set 3  the local lights' shadow maps (LocalLightShadows::set_bindings);
// and push constants of a fixed size (the draw's light or lights).

#include "tilelight/vulkan/vk_handles.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string_view>
#include <vector>

namespace shadergen {
struct Registry;
}

namespace tilelight {

class Context;

struct LightTargetLayout {
  std::vector<VkDescriptorSetLayoutBinding> set0;  // as reflected: what the pass must write
  UniqueDescriptorSetLayout set0_layout, set1_layout, set3_layout;
  UniquePipelineLayout pipeline;
  VkShaderStageFlags push_stages = 0;  // the stages that read the push constants
};

// `pass` names the pass in messages ("local-light", "forward"); `push_source` the GLSL file that
// declares the push constants. Throws tilelight::Error where the reflection differs from the
// shape above or the shaders push other than `push_bytes` bytes.
LightTargetLayout create_light_target_layout(const Context& context, const shadergen::Registry& registry,
                                             VkDescriptorSetLayout texture_set_layout, std::uint32_t push_bytes,
                                             std::string_view pass, std::string_view push_source);

}  // namespace tilelight
