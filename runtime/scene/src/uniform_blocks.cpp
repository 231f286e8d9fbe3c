#include "tilelight/scene/uniform_blocks.h"

namespace tilelight {
namespace {

glm::vec4 viewport_vector(std::uint32_t width, std::uint32_t height) {
  const auto w = static_cast<float>(width);
  const auto h = static_cast<float>(height);
  return {w, h, 1.0f / w, 1.0f / h};
}

}  // namespace

LightingParamsBlock make_lighting_params(const Scene& scene, const Camera& camera, std::uint32_t width,
                                         std::uint32_t height) {
  const SunAndAtmosphere& sun = scene.sun;
  const CameraMatrices matrices = camera_matrices(camera, static_cast<float>(width) / static_cast<float>(height));
  LightingParamsBlock block{};
  block.inv_view_proj = matrices.inv_view_proj;
  block.sun_view_proj = sun_view_proj(sun, camera);
  block.camera_pos = glm::vec4(camera.position, 1.0f);
  block.camera_forward = glm::vec4(matrices.forward, 0.0f);
  block.sun_direction = glm::vec4(sun.sun_direction, 0.0f);
  block.sun_color = glm::vec4(sun.sun_color, 1.0f);
  block.fog_color = glm::vec4(sun.fog_color, sun.fog_density);
  block.distances =
      glm::vec4(sun.shadow_fade_start, 1.0f / sun.shadow_fade_length, sun.scattering_start, sun.shadow_depth_bias);
  const auto map = static_cast<float>(sun.shadow_map_size);
  block.shadow_map_size = glm::vec4(map, map, 1.0f / map, 1.0f / map);
  block.viewport = viewport_vector(width, height);
  return block;
}

SceneParamsBlock make_scene_params(const Scene& scene, const Camera& camera, std::uint32_t width,
                                   std::uint32_t height) {
  const SunAndAtmosphere& sun = scene.sun;
  const CameraMatrices matrices = camera_matrices(camera, static_cast<float>(width) / static_cast<float>(height));
  SceneParamsBlock block{};
  block.view_proj = matrices.view_proj;
  block.inv_view_proj = matrices.inv_view_proj;
  block.sun_view_proj = sun_view_proj(sun, camera);
  block.camera_pos = glm::vec4(camera.position, 1.0f);
  block.sun_direction = glm::vec4(sun.sun_direction, 0.0f);
  block.sky_zenith = glm::vec4(sun.sky_zenith, 1.0f);
  block.sky_horizon = glm::vec4(sun.sky_horizon, 1.0f);
  block.ambient_sky = glm::vec4(sun.ambient_sky, 1.0f);
  block.ambient_ground = glm::vec4(sun.ambient_ground, 1.0f);
  block.viewport = viewport_vector(width, height);
  return block;
}

}  // namespace tilelight
