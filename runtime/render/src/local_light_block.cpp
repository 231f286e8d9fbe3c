#include "local_light_block.h"

#include "local_light_volumes.h"

#include <algorithm>
#include <cmath>

namespace tilelight {

glm::vec3 local_light_frame_x(glm::vec3 direction) {
  const glm::vec3 x = glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), direction);
  // Vertical (or nearly): world +y gives no axis, so world +x does (local_light.h).
  const float length = glm::length(x);
  return length > 1e-6f ? x / length : glm::vec3(1.0f, 0.0f, 0.0f);
}

LocalLightBlock make_local_light_block(const LocalLight& light) {
  const glm::vec3 z = light.direction;
  const glm::vec3 x = local_light_frame_x(z);
  const glm::vec3 y = glm::cross(z, x);
  const float outer = std::acos(std::clamp(light.outer_cone_cos, -1.0f, 1.0f));
  const glm::vec3 radiance = light.color * light.intensity;
  const glm::vec3 back = light.extras.back_color.value_or(glm::vec3(0.0f)) * light.intensity;
  LocalLightBlock block{};
  block.position_range = glm::vec4(light.position, light.range);
  block.direction_inner = glm::vec4(z, light.inner_cone_cos);
  block.radiance_outer = glm::vec4(radiance, light.outer_cone_cos);
  block.back_radiance_falloff = glm::vec4(back, light.box_falloff);
  block.frame_x = glm::vec4(x, std::tan(outer));
  block.frame_y = glm::vec4(y, 0.0f);
  block.box_half_extent = glm::vec4(light.box_half_extent, 0.0f);
  block.kind = glm::uvec4(static_cast<std::uint32_t>(light.type), static_cast<std::uint32_t>(volume_of(light)), 0u, 0u);
  return block;
}

std::vector<LocalLightBlock> make_local_light_blocks(const std::vector<LocalLight>& lights) {
  std::vector<LocalLightBlock> blocks;
  blocks.reserve(lights.size());
  for (const LocalLight& light : lights) blocks.push_back(make_local_light_block(light));
  return blocks;
}

}  // namespace tilelight
