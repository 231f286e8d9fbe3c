// The forward pass's CPU decisions (runtime/render/src/forward_selection.h): which instances it
// draws and in what order (back to front by bounding-box centre, ties in scene order, only blended
// meshes), and which local lights light each (the K most important, §19.3.3).
#include "forward_selection.h"
#include "tilelight/scene/scene.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <vector>

namespace tilelight {
namespace {

// A unit quad in the xy plane around the origin.
Mesh quad(bool blend) {
  Mesh mesh;
  mesh.name = blend ? "glass" : "wall";
  for (const glm::vec2 corner :
       {glm::vec2(-0.5f, -0.5f), glm::vec2(0.5f, -0.5f), glm::vec2(0.5f, 0.5f), glm::vec2(-0.5f, 0.5f)}) {
    mesh.vertices.push_back({glm::vec3(corner, 0.0f), glm::vec3(0, 0, 1), glm::vec2(0.0f)});
  }
  mesh.indices = {0, 1, 2, 0, 2, 3};
  mesh.blend = blend;
  return mesh;
}

Instance at(glm::vec3 position) {
  Instance instance{};
  instance.model = glm::translate(glm::mat4(1.0f), position);
  return instance;
}

// Mesh 0 opaque, mesh 1 blended; instances of the blended one at `glass` (in this order), one
// opaque instance first.
Scene scene_with(const std::vector<glm::vec3>& glass) {
  Scene scene;
  scene.meshes = {quad(false), quad(true)};
  scene.instances.push_back(at({0, 0, -10}));
  for (const glm::vec3& p : glass) scene.instances.push_back(at(p));
  scene.batches = {{0, 0, 1}, {1, 1, static_cast<std::uint32_t>(glass.size())}};
  return scene;
}

LocalLight point_at(glm::vec3 position, float intensity, float range) {
  LocalLight light;
  light.type = LocalLightType::point;
  light.position = position;
  light.intensity = intensity;
  light.range = range;
  return light;
}

std::vector<std::uint32_t> instances_of(const std::vector<ForwardDraw>& draws) {
  std::vector<std::uint32_t> out;
  for (const ForwardDraw& d : draws) out.push_back(d.instance);
  return out;
}

TEST(ForwardSelection, BlendedInstancesOnlyFarthestFirstTiesInSceneOrder) {
  // Camera at the origin: instance 2 (z -8) is farthest, 1 and 3 tie at distance 4.
  const Scene scene = scene_with({{0, 0, -4}, {0, 0, -8}, {0, 4, 0}});
  const std::vector<ForwardDraw> draws = plan_forward_draws(scene, glm::vec3(0));
  EXPECT_EQ(instances_of(draws), (std::vector<std::uint32_t>{2, 1, 3}));
  for (const ForwardDraw& d : draws) EXPECT_EQ(d.mesh, 1u) << "the opaque mesh is not the forward pass's";
  EXPECT_TRUE(plan_forward_draws(scene_with({}), glm::vec3(0)).empty());
}

TEST(ForwardSelection, ImportanceIsZeroOutOfReachAndFallsWithDistance) {
  const WorldBox box{{-1, -1, -1}, {1, 1, 1}};
  EXPECT_EQ(local_light_importance(point_at({5, 0, 0}, 10, 3.9f), box), 0.0f) << "4 m from the box, range 3.9";
  EXPECT_GT(local_light_importance(point_at({5, 0, 0}, 10, 4.1f), box), 0.0f);
  EXPECT_GT(local_light_importance(point_at({2, 0, 0}, 10, 5), box),
            local_light_importance(point_at({3, 0, 0}, 10, 5), box));
  EXPECT_GT(local_light_importance(point_at({3, 0, 0}, 20, 5), box),
            local_light_importance(point_at({3, 0, 0}, 10, 5), box));
  EXPECT_EQ(local_light_importance(point_at({0, 0, 0}, 0, 5), box), 0.0f) << "a dark light";
  LocalLight box_light;
  box_light.type = LocalLightType::box;
  box_light.box_half_extent = glm::vec3(1.0f);  // half-diagonal sqrt(3)
  box_light.position = {2.7f, 0, 0};
  EXPECT_GT(local_light_importance(box_light, box), 0.0f);
  box_light.position = {2.8f, 0, 0};
  EXPECT_EQ(local_light_importance(box_light, box), 0.0f);
}

TEST(ForwardSelection, AtMostKLightsMostImportantFirst) {
  Scene scene = scene_with({{0, 0, 0}});
  // Light i at distance 1 + i from the quad's box (x >= 0.5), all in range; light 10 out of range.
  for (int i = 0; i < 10; ++i) scene.local_lights.push_back(point_at({1.5f + float(i), 0, 0}, 10, 20));
  scene.local_lights.push_back(point_at({30, 0, 0}, 10, 5));
  std::swap(scene.local_lights[0], scene.local_lights[9]);  // the nearest is now index 9
  const std::vector<ForwardDraw> draws = plan_forward_draws(scene, glm::vec3(0, 0, 10));
  ASSERT_EQ(draws.size(), 1u);
  ASSERT_EQ(draws[0].light_count, kForwardMaxLights);
  EXPECT_EQ(draws[0].lights[0], 9u);
  for (std::uint32_t k = 1; k < kForwardMaxLights; ++k) EXPECT_EQ(draws[0].lights[k], k) << k;

  scene.local_lights = {point_at({30, 0, 0}, 10, 5)};
  EXPECT_EQ(plan_forward_draws(scene, glm::vec3(0, 0, 10))[0].light_count, 0u) << "no light reaches it";
}

}  // namespace
}  // namespace tilelight
