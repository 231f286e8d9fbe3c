#include "forward_selection.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace tilelight {
namespace {

float max_channel(glm::vec3 c) { return std::max({c.r, c.g, c.b}); }

// The distance from `point` to the nearest point of `box` (0 inside it).
float distance_to_box(const WorldBox& box, glm::vec3 point) {
  return glm::length(glm::clamp(point, box.min, box.max) - point);
}

// local_light.glsl's point attenuation at distance d, d floored at 1 cm so that a light inside
// the box is very important rather than infinitely so.
float point_attenuation(float d, float range) {
  if (!(range > 0.0f) || d >= range) return 0.0f;
  const float ratio = d / range;
  const float window = std::clamp(1.0f - ratio * ratio * ratio * ratio, 0.0f, 1.0f);
  const float floored = std::max(d, 0.01f);
  return window * window / (floored * floored);
}

struct Ranked {
  std::uint32_t light;
  float importance;
};

void choose_lights(const std::vector<LocalLight>& lights, const WorldBox& box, ForwardDraw& draw) {
  std::vector<Ranked> ranked;
  for (std::uint32_t i = 0; i < lights.size(); ++i) {
    const float importance = local_light_importance(lights[i], box);
    if (importance > 0.0f) ranked.push_back({i, importance});
  }
  // Stable: equal importances keep the lower index first.
  std::stable_sort(ranked.begin(), ranked.end(),
                   [](const Ranked& a, const Ranked& b) { return a.importance > b.importance; });
  draw.light_count = static_cast<std::uint32_t>(std::min<std::size_t>(ranked.size(), kForwardMaxLights));
  for (std::uint32_t k = 0; k < draw.light_count; ++k) draw.lights[k] = ranked[k].light;
}

}  // namespace

float local_light_importance(const LocalLight& light, const WorldBox& box) {
  const float strength = light.intensity * max_channel(light.color);
  if (!(strength > 0.0f)) return 0.0f;
  const float d = distance_to_box(box, light.position);
  if (light.type == LocalLightType::box) {
    return d <= glm::length(light.box_half_extent) ? strength : 0.0f;
  }
  return strength * point_attenuation(d, light.range);
}

WorldBox instance_bounds(const Mesh& mesh, const Instance& instance) {
  WorldBox local = empty_world_box();
  for (const MeshVertex& v : mesh.vertices) add_point(local, v.position);
  WorldBox world = empty_world_box();
  for (const glm::vec3& corner : corners(local)) add_point(world, glm::vec3(instance.model * glm::vec4(corner, 1.0f)));
  return world;
}

std::vector<ForwardDraw> plan_forward_draws(const Scene& scene, glm::vec3 camera_position) {
  std::vector<ForwardDraw> draws;
  std::vector<float> distances;
  for (const MeshBatch& batch : scene.batches) {
    const Mesh& mesh = scene.meshes.at(batch.mesh);
    if (!mesh.blend || mesh.vertices.empty()) continue;
    for (std::uint32_t i = batch.first_instance; i < batch.first_instance + batch.instance_count; ++i) {
      const WorldBox box = instance_bounds(mesh, scene.instances.at(i));
      ForwardDraw draw;
      draw.mesh = batch.mesh;
      draw.instance = i;
      choose_lights(scene.local_lights, box, draw);
      draws.push_back(draw);
      distances.push_back(glm::length((box.min + box.max) * 0.5f - camera_position));
    }
  }
  std::vector<std::size_t> order(draws.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  // Farthest first; equal distances keep the scene's order (stable).
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return distances[a] > distances[b]; });
  std::vector<ForwardDraw> sorted;
  sorted.reserve(draws.size());
  for (const std::size_t i : order) sorted.push_back(draws[i]);
  return sorted;
}

}  // namespace tilelight
