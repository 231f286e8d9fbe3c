#include "tilelight/scene/batch_culling.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace tilelight {

std::vector<WorldBox> batch_bounds(const Scene& scene) {
  std::vector<WorldBox> meshes(scene.meshes.size(), empty_world_box());
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    for (const MeshVertex& v : scene.meshes[m].vertices) add_point(meshes[m], v.position);
  }
  std::vector<WorldBox> batches(scene.batches.size(), empty_world_box());
  for (std::size_t b = 0; b < scene.batches.size(); ++b) {
    const MeshBatch& batch = scene.batches[b];
    if (is_empty(meshes[batch.mesh])) continue;
    for (std::uint32_t i = 0; i < batch.instance_count; ++i) {
      const glm::mat4& model = scene.instances[batch.first_instance + i].model;
      for (const glm::vec3& corner : corners(meshes[batch.mesh]))
        add_point(batches[b], glm::vec3(model * glm::vec4(corner, 1.0f)));
    }
  }
  return batches;
}

bool outside_clip_volume(const glm::mat4& view_proj, const WorldBox& box) {
  constexpr float kMargin = 1e-4f;
  if (is_empty(box)) return true;
  std::array<glm::vec4, 8> clip;
  const std::array<glm::vec3, 8> world = corners(box);
  for (std::size_t i = 0; i < world.size(); ++i) clip[i] = view_proj * glm::vec4(world[i], 1.0f);
  // Each plane as a function that is negative outside: w + x, w - x, w + y, w - y, z, w - z. A
  // corner counts as outside only by a margin (relative to w) that covers the GPU's own
  // rounding of the same transform: a batch at a plane is drawn.
  const std::array<glm::vec4, 6> planes{glm::vec4(1, 0, 0, 1),  glm::vec4(-1, 0, 0, 1), glm::vec4(0, 1, 0, 1),
                                        glm::vec4(0, -1, 0, 1), glm::vec4(0, 0, 1, 0),  glm::vec4(0, 0, -1, 1)};
  return std::any_of(planes.begin(), planes.end(), [&](const glm::vec4& plane) {
    return std::all_of(clip.begin(), clip.end(),
                       [&](const glm::vec4& c) { return glm::dot(plane, c) < -kMargin * (std::abs(c.w) + 1.0f); });
  });
}

BatchSelection select_batches(const std::vector<WorldBox>& bounds, const glm::mat4& view_proj) {
  BatchSelection selection;
  selection.drawn.reserve(bounds.size());
  for (const WorldBox& box : bounds) {
    const bool outside = outside_clip_volume(view_proj, box);
    selection.drawn.push_back(!outside);
    selection.culled += outside ? 1 : 0;
  }
  return selection;
}

}  // namespace tilelight
