#include "light_target_layout.h"

#include "descriptors.h"
#include "local_light_shadows.h"
#include "pipelines.h"
#include "reflected_layout.h"
#include "tilelight/vulkan/error.h"

#include <shadergen/registry.h>
#include <shadergen/vulkan.h>

#include <array>
#include <string>

namespace tilelight {
namespace {

constexpr std::uint32_t kLightsSet = 1;
constexpr std::uint32_t kTextureSet = 2;

}  // namespace

LightTargetLayout create_light_target_layout(const Context& context, const shadergen::Registry& registry,
                                             VkDescriptorSetLayout texture_set_layout, std::uint32_t push_bytes,
                                             std::string_view pass, std::string_view push_source) {
  const std::string name(pass);
  LightTargetLayout layout;
  layout.set0 = merged_set_bindings({registry.pipeline_layout}, 0, name + " set 0");
  const std::vector<VkDescriptorSetLayoutBinding> set1 =
      merged_set_bindings({registry.pipeline_layout}, kLightsSet, name + " set 1");
  check_storage_buffers(set1, 1, name + " set 1 (the lights)");
  const std::vector<VkDescriptorSetLayoutBinding> set2 =
      merged_set_bindings({registry.pipeline_layout}, kTextureSet, name + " set 2");
  const std::array<VkDescriptorType, 1> texture_types{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER};
  check_bindings(set2, texture_types, name + " set 2 (a scene texture)");
  const std::vector<VkDescriptorSetLayoutBinding> set3 = LocalLightShadows::set_bindings(registry, pass);
  layout.set0_layout = create_descriptor_set_layout(context, layout.set0, name + " set 0 layout");
  layout.set1_layout = create_descriptor_set_layout(context, set1, name + " set 1 layout");
  layout.set3_layout = create_descriptor_set_layout(context, set3, name + " set 3 layout");
  const std::array<VkDescriptorSetLayout, 4> sets{layout.set0_layout.get(), layout.set1_layout.get(),
                                                  texture_set_layout, layout.set3_layout.get()};
  const std::vector<VkPushConstantRange> push = shadergen::vk::push_constant_ranges(registry);
  if (push_constant_bytes(push) != push_bytes) {
    throw Error(name + " shaders push " + std::to_string(push_constant_bytes(push)) + " bytes; the runtime pushes " +
                std::to_string(push_bytes) + " (" + std::string(push_source) + ")");
  }
  layout.push_stages = push.front().stageFlags;
  layout.pipeline = create_pipeline_layout(context, sets, push, name + " pipeline layout");
  return layout;
}

}  // namespace tilelight
