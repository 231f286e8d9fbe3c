#pragma once
// Fitting the clip planes, the sun's shadow map and the shadow-fade and scattering distances
// to one camera's view of a scene. The procedural scene's named cameras come with hand-set
// values (make_demo_sun, demo_cameras); a camera placed anywhere (--eye, a glTF file's camera)
// or any view of a loaded scene gets them from here, so an interior view keeps its shadows, its
// near geometry and a shadow map that covers what it sees rather than the whole scene.

#include "tilelight/scene/scene.h"
#include "tilelight/scene/world_box.h"

#include <glm/glm.hpp>

#include <optional>

namespace tilelight {

// The world bounds of every instance's mesh. Precondition: at least one instance.
WorldBox world_box(const Scene& scene);

// Sets camera.near_plane and far_plane so that every part of `box` in front of the camera lies
// between them, the near plane no closer than far / 2000 (depth precision).
void fit_clip_planes(Camera& camera, const WorldBox& box);

// Shadow fade and scattering measured from the eye, as a game sets them: fixed view depths.
// Unset values start at the far side of `box` as the camera sees it, so no visible surface of
// the scene loses its shadow or is fogged; the fade then runs over a quarter of the box's
// diagonal.
struct LightingDistances {
  std::optional<float> shadow_fade_start, shadow_fade_length, scattering_start;  // view depths, > 0
};
void fit_lighting_distances(SunAndAtmosphere& sun, const Camera& camera, const WorldBox& box,
                            const LightingDistances& chosen);

// Centres and sizes the sun's orthographic shadow map (camera.shadow_focus, sun.shadow_half_extent,
// shadow_depth_range, shadow_depth_bias) on the part of `box` the camera sees up to where its
// shadows have faded, for a frame of `aspect` (width / height). The depth range covers the
// whole box along the sun, since casters outside the view still shade what is in it.
void fit_shadow_map(SunAndAtmosphere& sun, Camera& camera, const WorldBox& box, float aspect);

}  // namespace tilelight
