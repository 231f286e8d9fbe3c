#pragma once
// Placing a loaded scene in the renderer's world: glTF files come in any size, while the
// renderer's near plane (0.5 m), the sun's shadow map and the fade and scattering distances
// are in metres. So the scene is scaled uniformly and centred, then lit by the demo's sun with
// its shadow map fitted to the scene, and seen from a default camera that frames it.

#include "tilelight/scene/scene.h"

#include <glm/glm.hpp>

namespace tilelight::gltf_detail {

// The radius of the sphere around the scene's bounding box after fit_scene(), in metres.
inline constexpr float kSceneRadius = 10.0f;

struct Bounds {
  glm::vec3 min{0.0f}, max{0.0f};
};

// World-space bounds of every instance's mesh. Precondition: at least one instance.
Bounds scene_bounds(const Scene& scene);

// Scales and moves every instance so that `bounds` (the scene's, non-degenerate and finite)
// becomes a box centred on the origin whose bounding sphere has kSceneRadius; sets the demo's
// sun with the shadow map covering that sphere, the shadow-fade and scattering distances from
// the scene's far side as the default camera sees it, Scene::world_from_file, and the cameras: "default", a raised
// three-quarter view framing the box in the vertical field of view and a 4:3 frame's width. Throws tilelight::Error when a
// transform becomes non-finite.
void fit_scene(Scene& scene, const Bounds& bounds);

}  // namespace tilelight::gltf_detail
