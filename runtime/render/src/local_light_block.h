#pragma once
// A local light as the local-light shaders read it: LocalLightData of uber/include/local_light.glsl,
// field for field (std430, 16-byte vectors), one array element per light of the scene. The CPU
// derives here what the shaders would otherwise recompute per pixel: colour times intensity,
// the light's frame (the box's axes as local_light.h defines them, also the spot's globe
// frame), tan of the outer cone.

#include "tilelight/scene/local_light.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace tilelight {

struct LocalLightBlock {
  glm::vec4 position_range;
  glm::vec4 direction_inner;
  glm::vec4 radiance_outer;
  glm::vec4 back_radiance_falloff;
  glm::vec4 frame_x;  // w: tan(outer cone angle)
  glm::vec4 frame_y;
  glm::vec4 box_half_extent;
  glm::uvec4 kind;  // x: 0 point, 1 spot, 2 box (LocalLightType); y: its LightVolume; z, w: its shadow
                    // faces, first and count (0: none; LocalLightPasses fills them)
};
static_assert(sizeof(LocalLightBlock) == 128, "std430 layout of LocalLightData (local_light.glsl)");

// The x and y axes of a light whose z axis is `direction` (normalised): x perpendicular to it and
// to world +y, world +x where `direction` is vertical; y completes a right-handed frame.
glm::vec3 local_light_frame_x(glm::vec3 direction);

LocalLightBlock make_local_light_block(const LocalLight& light);
std::vector<LocalLightBlock> make_local_light_blocks(const std::vector<LocalLight>& lights);

}  // namespace tilelight
