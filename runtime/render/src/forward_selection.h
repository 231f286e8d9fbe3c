#pragma once
// What the forward pass draws, decided once on the CPU (docs/local-lights.md, "Forward pass for
// blended materials"): every instance of a blended (glTF BLEND) mesh, sorted back to front by
// the distance from the camera to its world bounding box's centre, ties in scene order; and
// for each, the K most important local lights (Tabula Rasa §19.3.3), K = kForwardMaxLights.
// Triangles within one instance are drawn in index order, not sorted.

#include "tilelight/render/tile_renderer.h"
#include "tilelight/scene/scene.h"
#include "tilelight/scene/world_box.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace tilelight {

// kForwardMaxLights (tile_renderer.h) is uber/include/forward_params.glsl's FORWARD_MAX_LIGHTS.
static_assert(kForwardMaxLights == 8 && kForwardMaxLights % 4 == 0, "forward_params.glsl packs 4 per uvec4");

struct ForwardDraw {
  std::uint32_t mesh = 0;      // index into Scene::meshes (a blended mesh)
  std::uint32_t instance = 0;  // index into Scene::instances
  std::uint32_t light_count = 0;
  std::array<std::uint32_t, kForwardMaxLights> lights{};  // into Scene::local_lights, most important first
};

// How much `light` matters to a surface inside `box` (§19.3.3): intensity times the brightest
// colour channel times the light's attenuation at the point of `box` nearest to it (point and
// spot: KHR_lights_punctual's window over inverse square, the distance floored at 1 cm; box: 1
// where `box` reaches within the box light's half-diagonal of its centre). Exactly 0 where the
// light cannot reach the box; spots count as points (their cone is ignored: conservative).
float local_light_importance(const LocalLight& light, const WorldBox& box);

// The world box of one instance of `mesh`. Precondition: the mesh has vertices.
WorldBox instance_bounds(const Mesh& mesh, const Instance& instance);

// The blended instances of `scene` back to front as seen from `camera_position`, each with its
// lights: those of importance > 0, most important first (ties: lower index first), at most
// kForwardMaxLights. Deterministic.
std::vector<ForwardDraw> plan_forward_draws(const Scene& scene, glm::vec3 camera_position);

}  // namespace tilelight
