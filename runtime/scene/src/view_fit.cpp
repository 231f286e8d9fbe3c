#include "tilelight/scene/view_fit.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace tilelight {
namespace {

glm::vec3 forward_of(const Camera& camera) { return glm::normalize(camera.target - camera.position); }

float diagonal(const WorldBox& box) { return glm::length(box.max - box.min); }

// The nearest and farthest view depth of the box's corners.
std::pair<float, float> depth_range(const Camera& camera, const WorldBox& box) {
  const glm::vec3 forward = forward_of(camera);
  float nearest = std::numeric_limits<float>::max(), farthest = std::numeric_limits<float>::lowest();
  for (const glm::vec3& c : corners(box)) {
    const float depth = glm::dot(c - camera.position, forward);
    nearest = std::min(nearest, depth);
    farthest = std::max(farthest, depth);
  }
  return {nearest, farthest};
}

// The sun's view (as sun_view_proj orients it) with its eye at the origin.
glm::mat4 sun_view(const SunAndAtmosphere& sun) {
  const glm::vec3 up = std::abs(sun.sun_direction.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
  return glm::lookAtRH(sun.sun_direction, glm::vec3(0.0f), up);
}

// The camera's view frustum between two view depths: its eight corners.
std::array<glm::vec3, 8> frustum_slice(const Camera& camera, float aspect, float near_depth, float far_depth) {
  const glm::vec3 forward = forward_of(camera);
  const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
  const glm::vec3 up = glm::cross(right, forward);
  const float tan_y = std::tan(glm::radians(camera.vertical_fov_degrees) * 0.5f);
  std::array<glm::vec3, 8> c{};
  for (int i = 0; i < 8; ++i) {
    const float depth = (i & 4) != 0 ? far_depth : near_depth;
    const float sx = (i & 1) != 0 ? 1.0f : -1.0f, sy = (i & 2) != 0 ? 1.0f : -1.0f;
    c[static_cast<std::size_t>(i)] =
        camera.position + depth * (forward + sx * tan_y * aspect * right + sy * tan_y * up);
  }
  return c;
}

template <std::size_t N>
WorldBox box_of(const glm::mat4& transform, const std::array<glm::vec3, N>& points) {
  WorldBox b = empty_world_box();
  for (const glm::vec3& p : points) add_point(b, glm::vec3(transform * glm::vec4(p, 1.0f)));
  return b;
}

}  // namespace

WorldBox world_box(const Scene& scene) {
  WorldBox b = empty_world_box();
  for (const MeshBatch& batch : scene.batches) {
    const Mesh& mesh = scene.meshes[batch.mesh];
    for (std::uint32_t i = 0; i < batch.instance_count; ++i) {
      const glm::mat4& model = scene.instances[batch.first_instance + i].model;
      for (const MeshVertex& v : mesh.vertices) add_point(b, glm::vec3(model * glm::vec4(v.position, 1.0f)));
    }
  }
  return b;
}

void fit_clip_planes(Camera& camera, const WorldBox& box) {
  const auto [nearest, farthest] = depth_range(camera, box);
  // A box wholly behind the camera shows nothing; any planes of the scene's size will do.
  camera.far_plane = std::max(farthest * 1.01f, diagonal(box) * 0.01f);
  camera.near_plane = std::max(nearest * 0.99f, camera.far_plane / 2000.0f);
}

void fit_lighting_distances(SunAndAtmosphere& sun, const Camera& camera, const WorldBox& box,
                            const LightingDistances& chosen) {
  const float far_side = std::max(depth_range(camera, box).second, 0.0f);
  sun.shadow_fade_start = chosen.shadow_fade_start.value_or(far_side);
  sun.shadow_fade_length = chosen.shadow_fade_length.value_or(std::max(0.25f * diagonal(box), 1e-3f));
  sun.scattering_start = chosen.scattering_start.value_or(far_side);
}

void fit_shadow_map(SunAndAtmosphere& sun, Camera& camera, const WorldBox& box, float aspect) {
  const glm::mat4 view = sun_view(sun);
  const float shadowed_depth =
      std::clamp(sun.shadow_fade_start + sun.shadow_fade_length, camera.near_plane, camera.far_plane);
  const WorldBox seen = box_of(view, frustum_slice(camera, aspect, camera.near_plane, shadowed_depth));
  const WorldBox scene = box_of(view, corners(box));
  // Across the sun: what the camera sees of the scene (the scene's box where the two miss).
  WorldBox fit{glm::max(seen.min, scene.min), glm::min(seen.max, scene.max)};
  if (fit.min.x > fit.max.x || fit.min.y > fit.max.y) fit = scene;
  const float half_extent =
      std::max({(fit.max.x - fit.min.x) * 0.5f, (fit.max.y - fit.min.y) * 0.5f, diagonal(box) * 1e-3f}) * 1.02f;
  // Along the sun: the whole scene, with a margin.
  const float depth_range_needed = std::max((scene.max.z - scene.min.z) * 1.1f, diagonal(box) * 1e-3f);
  const glm::vec3 centre((fit.min.x + fit.max.x) * 0.5f, (fit.min.y + fit.max.y) * 0.5f,
                         (scene.min.z + scene.max.z) * 0.5f);
  camera.shadow_focus = glm::vec3(glm::inverse(view) * glm::vec4(centre, 1.0f));
  sun.shadow_half_extent = half_extent;
  sun.shadow_depth_range = depth_range_needed;
  // About three texels of bias against self-shadowing acne, as the loaded scenes' fit has.
  const float texel = 2.0f * half_extent / static_cast<float>(sun.shadow_map_size);
  sun.shadow_depth_bias = 3.0f * texel / depth_range_needed;
}

}  // namespace tilelight
