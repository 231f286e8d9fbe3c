#include "scene_framing.h"

#include "tilelight/base/error.h"
#include "tilelight/scene/view_fit.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace tilelight::gltf_detail {
namespace {

constexpr float kVerticalFovDegrees = 40.0f;

bool finite(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      if (!std::isfinite(m[c][r])) return false;
    }
  }
  return true;
}

}  // namespace

Bounds scene_bounds(const Scene& scene) {
  Bounds b{glm::vec3(INFINITY), glm::vec3(-INFINITY)};
  for (const MeshBatch& batch : scene.batches) {
    const Mesh& mesh = scene.meshes[batch.mesh];
    for (std::uint32_t i = 0; i < batch.instance_count; ++i) {
      const glm::mat4& model = scene.instances[batch.first_instance + i].model;
      for (const MeshVertex& v : mesh.vertices) {
        const glm::vec3 p = glm::vec3(model * glm::vec4(v.position, 1.0f));
        b.min = glm::min(b.min, p);
        b.max = glm::max(b.max, p);
      }
    }
  }
  return b;
}

void fit_scene(Scene& scene, const Bounds& bounds) {
  const glm::vec3 centre = (bounds.min + bounds.max) * 0.5f;
  const float radius = glm::length(bounds.max - bounds.min) * 0.5f;
  if (!std::isfinite(radius) || !std::isfinite(centre.x) || !std::isfinite(centre.y) || !std::isfinite(centre.z)) {
    throw Error("the scene's bounds are not finite (vertices too far apart for 32-bit floats)");
  }
  if (!(radius > 0.0f)) throw Error("every vertex of the scene is at one point: nothing to draw");
  const glm::mat4 normalise =
      glm::scale(glm::mat4(1.0f), glm::vec3(kSceneRadius / radius)) * glm::translate(glm::mat4(1.0f), -centre);
  for (Instance& instance : scene.instances) {
    instance.model = normalise * instance.model;
    if (!finite(instance.model)) throw Error("a node's transform is not finite once the scene is scaled to metres");
  }

  // The default camera: a raised three-quarter view at the nearest distance where every corner
  // of the scene's box lies inside the vertical field of view and inside the horizontal one of
  // a 4:3 frame (wider frames see more). Its view direction points at the box's centre.
  const glm::vec3 towards_camera = glm::normalize(glm::vec3(0.55f, 0.45f, 0.70f));
  const glm::vec3 forward = -towards_camera;
  const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f)));
  const glm::vec3 up = glm::cross(right, forward);
  const float tan_vertical = std::tan(glm::radians(kVerticalFovDegrees * 0.5f));
  const float tan_horizontal = tan_vertical * 4.0f / 3.0f;
  const glm::vec3 half = (bounds.max - bounds.min) * 0.5f * (kSceneRadius / radius);
  float distance = 0.0f;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 c{(corner & 1) != 0 ? half.x : -half.x, (corner & 2) != 0 ? half.y : -half.y,
                      (corner & 4) != 0 ? half.z : -half.z};
    // At distance d the corner's view depth is d + dot(c, forward).
    const float depth_offset = glm::dot(c, forward);
    distance = std::max(distance, std::fabs(glm::dot(c, up)) / tan_vertical - depth_offset);
    distance = std::max(distance, std::fabs(glm::dot(c, right)) / tan_horizontal - depth_offset);
  }
  // A margin, and never inside the sphere (the near plane is 0.5 m).
  distance = std::max(distance * 1.08f, kSceneRadius * 1.2f);
  Camera camera;
  camera.name = "default";
  camera.description = "a raised three-quarter view framing the whole scene";
  camera.position = towards_camera * distance;
  camera.target = glm::vec3(0.0f);
  camera.vertical_fov_degrees = kVerticalFovDegrees;
  camera.shadow_focus = glm::vec3(0.0f);
  scene.cameras = {camera};

  // The sun's orthographic shadow map: a square of the sphere's diameter, a depth range a
  // little deeper than the sphere, a bias of about three texels.
  scene.sun = make_demo_sun();
  scene.sun.shadow_half_extent = kSceneRadius * 1.02f;
  scene.sun.shadow_depth_range = kSceneRadius * 2.2f;
  const float texel = 2.0f * scene.sun.shadow_half_extent / static_cast<float>(scene.sun.shadow_map_size);
  scene.sun.shadow_depth_bias = 3.0f * texel / scene.sun.shadow_depth_range;
  // Shadows fade and light scatters from the scene's far side as the camera sees it (view
  // depths from the eye), so no visible surface loses its shadow (view_fit.h).
  fit_lighting_distances(scene.sun, scene.cameras.front(), WorldBox{-half, half}, {});
  scene.world_from_file = normalise;
}

}  // namespace tilelight::gltf_detail
