#pragma once
// Host mirrors of the shaders' uniform blocks (std140). Field order and types must match
// uber/include/lighting_params.glsl and uber/include/scene_params.glsl; every member is a
// vec4 or mat4, so std140 adds no padding and the static_asserts below pin the sizes.

#include "tilelight/scene/scene.h"

#include <glm/glm.hpp>

#include <cstdint>

namespace tilelight {

struct LightingParamsBlock {
  glm::mat4 inv_view_proj;
  glm::mat4 sun_view_proj;
  glm::vec4 camera_pos;
  glm::vec4 camera_forward;
  glm::vec4 sun_direction;
  glm::vec4 sun_color;
  glm::vec4 fog_color;        // a = density
  glm::vec4 distances;        // fade start, 1/fade length, scattering start, shadow depth bias
  glm::vec4 shadow_map_size;  // texels, 1/texels
  glm::vec4 viewport;         // pixels, 1/pixels
};
static_assert(sizeof(LightingParamsBlock) == 2 * 64 + 8 * 16);

struct SceneParamsBlock {
  glm::mat4 view_proj;
  glm::mat4 inv_view_proj;
  glm::mat4 sun_view_proj;
  glm::vec4 camera_pos;
  glm::vec4 sun_direction;
  glm::vec4 sky_zenith;
  glm::vec4 sky_horizon;
  glm::vec4 ambient_sky;
  glm::vec4 ambient_ground;
  glm::vec4 viewport;
};
static_assert(sizeof(SceneParamsBlock) == 3 * 64 + 7 * 16);

// Both blocks for one camera and framebuffer size.
LightingParamsBlock make_lighting_params(const Scene& scene, const Camera& camera, std::uint32_t width,
                                         std::uint32_t height);
SceneParamsBlock make_scene_params(const Scene& scene, const Camera& camera, std::uint32_t width, std::uint32_t height);

}  // namespace tilelight
