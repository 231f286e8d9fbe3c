// The procedural scene's lights (tilelight --lights N, local_light_placement.h): the same on every
// run, the first N of one sequence, types cycling, on the demo's ground where its cameras see
// them, reaching the ground, as bright there as the sun, with back colours and globe maps on some.
#include "tilelight/scene/local_light_placement.h"
#include "tilelight/scene/local_light_counts.h"
#include "tilelight/scene/scene.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace tilelight {
namespace {

bool same(const LocalLight& a, const LocalLight& b) {
  return a.type == b.type && a.position == b.position && a.direction == b.direction && a.color == b.color &&
         a.intensity == b.intensity && a.range == b.range && a.inner_cone_cos == b.inner_cone_cos &&
         a.outer_cone_cos == b.outer_cone_cos && a.box_half_extent == b.box_half_extent &&
         a.box_falloff == b.box_falloff && a.casts_shadows == b.casts_shadows &&
         a.extras.back_color == b.extras.back_color && a.extras.globe_texture == b.extras.globe_texture;
}

TEST(DemoLights, EveryRunPlacesTheSameLightsAndFewerAreAPrefixOfMore) {
  const std::vector<LocalLight> a = make_demo_lights(64, 0);
  const std::vector<LocalLight> b = make_demo_lights(64, 0);
  const std::vector<LocalLight> first = make_demo_lights(16, 0);
  ASSERT_EQ(a.size(), 64u);
  ASSERT_EQ(first.size(), 16u);
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_TRUE(same(a[i], b[i])) << i;
  for (std::size_t i = 0; i < first.size(); ++i) EXPECT_TRUE(same(a[i], first[i])) << i;
}

TEST(DemoLights, TheCountIsTheOneAskedFor) {
  for (std::uint32_t n : {0u, 1u, 4u, 256u, kMaxDemoLights}) EXPECT_EQ(make_demo_lights(n, 0).size(), n);
}

TEST(DemoLights, TypesCyclePointSpotBoxAndEveryLightCastsShadows) {
  const std::vector<LocalLight> lights = make_demo_lights(12, 0);
  const LocalLightType cycle[] = {LocalLightType::point, LocalLightType::spot, LocalLightType::box};
  for (std::size_t i = 0; i < lights.size(); ++i) {
    EXPECT_EQ(lights[i].type, cycle[i % 3]) << i;
    EXPECT_TRUE(lights[i].casts_shadows) << i;
  }
  const LocalLightCounts counts = count_local_lights(make_demo_lights(64, 0));
  EXPECT_EQ(counts.point, 22u);
  EXPECT_EQ(counts.spot, 21u);
  EXPECT_EQ(counts.box, 21u);
}

TEST(DemoLights, SomeBoxLightsHaveBackColoursAndEveryTypeHasGlobeMaps) {
  const std::vector<LocalLight> lights = make_demo_lights(12, 7);
  std::size_t back = 0;
  bool globe[3] = {false, false, false};
  for (const LocalLight& light : lights) {
    if (light.extras.back_color) {
      EXPECT_EQ(light.type, LocalLightType::box) << "only box lights have back colours";
      ++back;
    }
    if (light.extras.globe_texture) {
      EXPECT_EQ(*light.extras.globe_texture, 7u);
      globe[static_cast<int>(light.type)] = true;
    }
  }
  EXPECT_EQ(back, 2u);
  EXPECT_TRUE(globe[0] && globe[1] && globe[2]);
}

TEST(DemoLights, EveryLightStandsOnTheGroundAndItsVolumeReachesIt) {
  for (const LocalLight& light : make_demo_lights(kMaxDemoLights, 0)) {
    EXPECT_LT(std::max(std::abs(light.position.x), std::abs(light.position.z)), 300.0f) << "on the demo's ground";
    EXPECT_GT(light.position.y, 0.0f);
    if (light.type == LocalLightType::box) {
      EXPECT_LT(light.position.y - light.box_half_extent.z, 0.0f) << "the box's lower face is below the ground";
      EXPECT_LE(light.box_falloff,
                std::min({light.box_half_extent.x, light.box_half_extent.y, light.box_half_extent.z}));
    } else {
      EXPECT_GT(light.range, light.position.y) << "the light reaches the ground";
      EXPECT_LT(light.range, 10.0f) << "a few metres";
    }
    if (light.type == LocalLightType::spot) {
      EXPECT_GT(light.inner_cone_cos, light.outer_cone_cos);
    }
  }
}

TEST(DemoLights, NeighboursOverlapALittle) {
  const std::vector<LocalLight> lights = make_demo_lights(2, 0);
  const float apart =
      glm::length(glm::vec2(lights[0].position.x - lights[1].position.x, lights[0].position.z - lights[1].position.z));
  EXPECT_GT(apart, 4.0f);
  EXPECT_LT(apart, lights[0].range + lights[1].range);
}

// Whether `p` lies inside the camera's view (a 16:9 frame).
bool seen_by(const Camera& camera, const glm::vec3& p) {
  const glm::vec4 clip = camera_matrices(camera, 16.0f / 9.0f).view_proj * glm::vec4(p, 1.0f);
  return clip.w > 0.0f && std::abs(clip.x) <= clip.w && std::abs(clip.y) <= clip.w && clip.z >= 0.0f &&
         clip.z <= clip.w;
}

TEST(DemoLights, TheStreetAndDefaultCamerasSeeTheFirstLightsPools) {
  const Scene scene = make_demo_scene();
  const std::vector<LocalLight> lights = make_demo_lights(4, 0);
  for (const char* camera : {"street", "default"}) {
    for (std::size_t i = 0; i < lights.size(); ++i) {
      const glm::vec3 pool{lights[i].position.x, 0.0f, lights[i].position.z};
      EXPECT_TRUE(seen_by(scene.camera(camera), pool)) << camera << " light " << i;
    }
  }
}

TEST(DemoLights, TheirPoolsAreAboutAsBrightAsTheSunOnTheGround) {
  const SunAndAtmosphere sun = make_demo_sun();
  const float sun_on_ground = std::max({sun.sun_color.x, sun.sun_color.y, sun.sun_color.z}) * sun.sun_direction.y;
  for (const LocalLight& light : make_demo_lights(3, 0)) {
    const float below = light.type == LocalLightType::box
                            ? light.intensity
                            : light.intensity / (light.position.y * light.position.y);  // inverse square
    EXPECT_GT(below / sun_on_ground, 0.5f) << static_cast<int>(light.type) << ": not swamped by the sun";
    EXPECT_LT(below / sun_on_ground, 3.0f) << static_cast<int>(light.type) << ": not swamping it";
  }
}

TEST(DemoLights, AddingThemPutsTheGlobeTextureInTheSceneForTheLightsThatUseIt) {
  Scene scene = make_demo_scene();
  const std::size_t textures = scene.textures.size();
  add_demo_lights(scene, 8);
  ASSERT_EQ(scene.local_lights.size(), 8u);
  ASSERT_EQ(scene.textures.size(), textures + 1);
  const Texture& globe = scene.textures.back();
  EXPECT_EQ(globe.rgba.size(), std::size_t{globe.width} * globe.height * 4);
  EXPECT_EQ(*scene.local_lights[1].extras.globe_texture, textures);
  // A pattern: dark leading between coloured panes.
  const auto red = [&](std::uint32_t x, std::uint32_t y) { return globe.rgba[(y * globe.width + x) * 4]; };
  EXPECT_LT(red(0, 0), 40);
  EXPECT_GT(red(4, 4), 200);

  Scene none = make_demo_scene();
  add_demo_lights(none, 0);
  EXPECT_TRUE(none.local_lights.empty());
  EXPECT_EQ(none.textures.size(), textures) << "no lights, no texture";
}

TEST(LocalLightCounts, CountsEachType) {
  std::vector<LocalLight> lights(5);
  lights[1].type = LocalLightType::spot;
  lights[2].type = LocalLightType::box;
  lights[3].type = LocalLightType::box;
  const LocalLightCounts counts = count_local_lights(lights);
  EXPECT_EQ(counts.point, 2u);
  EXPECT_EQ(counts.spot, 1u);
  EXPECT_EQ(counts.box, 2u);
}

}  // namespace
}  // namespace tilelight
