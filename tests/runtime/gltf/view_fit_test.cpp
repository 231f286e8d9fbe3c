// The view fit (tilelight/scene/view_fit.h), on the CPU: clip planes around what the camera
// sees, distances measured from the eye, and a shadow map over the seen part of the scene.
#include "tilelight/scene/view_fit.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace tilelight {
namespace {

// A 100 m square field, 20 m high, seen from inside its corner towards the corner's
// diagonal neighbour region: about a sixth of the field is in view up to the fade's end.
const WorldBox kField{{-50.0f, 0.0f, -50.0f}, {50.0f, 20.0f, 50.0f}};

Camera corner_camera() {
  Camera camera;
  camera.position = {-45.0f, 2.0f, 45.0f};
  camera.target = {-35.0f, 1.0f, 35.0f};
  camera.vertical_fov_degrees = 60.0f;
  return camera;
}

TEST(ViewFit, ClipPlanesHoldTheSceneInFrontOfTheEye) {
  Camera camera = corner_camera();
  fit_clip_planes(camera, kField);
  const glm::vec3 forward = glm::normalize(camera.target - camera.position);
  const float far_corner = glm::dot(glm::vec3(50.0f, 0.0f, -50.0f) - camera.position, forward);
  EXPECT_GE(camera.far_plane, far_corner);
  EXPECT_LT(camera.far_plane, far_corner * 1.05f);
  EXPECT_GT(camera.near_plane, 0.0f);
  EXPECT_LE(camera.near_plane, camera.far_plane / 1999.0f) << "the eye is inside the box: the near plane is close";
}

TEST(ViewFit, DistancesAreViewDepthsFromTheEyeUnlessChosen) {
  const Camera camera = corner_camera();
  SunAndAtmosphere sun = make_demo_sun();
  fit_lighting_distances(sun, camera, kField, {});
  const glm::vec3 forward = glm::normalize(camera.target - camera.position);
  float farthest = 0.0f;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 c{(i & 1) != 0 ? kField.max.x : kField.min.x, (i & 2) != 0 ? kField.max.y : kField.min.y,
                      (i & 4) != 0 ? kField.max.z : kField.min.z};
    farthest = std::max(farthest, glm::dot(c - camera.position, forward));
  }
  EXPECT_FLOAT_EQ(sun.shadow_fade_start, farthest);
  EXPECT_FLOAT_EQ(sun.scattering_start, farthest);
  fit_lighting_distances(sun, camera, kField, {12.0f, 3.0f, 40.0f});
  EXPECT_EQ(sun.shadow_fade_start, 12.0f);
  EXPECT_EQ(sun.shadow_fade_length, 3.0f);
  EXPECT_EQ(sun.scattering_start, 40.0f);
}

TEST(ViewFit, TheShadowMapCoversWhatTheCameraSeesAndNotTheWholeScene) {
  Camera camera = corner_camera();
  fit_clip_planes(camera, kField);
  SunAndAtmosphere sun = make_demo_sun();
  fit_lighting_distances(sun, camera, kField, {20.0f, 10.0f, std::nullopt});
  constexpr float kAspect = 16.0f / 9.0f;
  fit_shadow_map(sun, camera, kField, kAspect);
  EXPECT_LT(sun.shadow_half_extent, 35.0f) << "a 30 m view of a 100 m field";
  // Every point of the field the camera sees before its shadows have faded lies in the map.
  const glm::mat4 sun_clip = sun_view_proj(sun, camera);
  const CameraMatrices view = camera_matrices(camera, kAspect);
  int seen = 0;
  for (float x = -50.0f; x <= 50.0f; x += 2.5f) {
    for (float z = -50.0f; z <= 50.0f; z += 2.5f) {
      for (float y : {0.0f, 10.0f, 20.0f}) {
        const glm::vec4 p(x, y, z, 1.0f);
        const glm::vec4 clip = view.view_proj * p;
        const bool in_view = clip.w > 0.0f && std::fabs(clip.x) <= clip.w && std::fabs(clip.y) <= clip.w &&
                             clip.w <= sun.shadow_fade_start + sun.shadow_fade_length;
        if (!in_view) continue;
        ++seen;
        const glm::vec4 s = sun_clip * p;
        EXPECT_LE(std::fabs(s.x), 1.0f) << x << "," << y << "," << z;
        EXPECT_LE(std::fabs(s.y), 1.0f) << x << "," << y << "," << z;
        EXPECT_GE(s.z, 0.0f);
        EXPECT_LE(s.z, 1.0f);
      }
    }
  }
  EXPECT_GT(seen, 20);
}

}  // namespace
}  // namespace tilelight
