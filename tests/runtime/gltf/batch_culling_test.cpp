// Batch culling (tilelight/scene/batch_culling.h), on the CPU: world bounds of each batch, and
// which of them lie wholly outside a clip volume.
#include "tilelight/scene/batch_culling.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

namespace tilelight {
namespace {

// Looking down -z from the origin, 90 degrees, depth 0..1 from 1 to 100 (Vulkan clip space).
glm::mat4 looking_down_minus_z() {
  return glm::perspectiveRH_ZO(glm::radians(90.0f), 1.0f, 1.0f, 100.0f) *
         glm::lookAtRH(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 1.0f, 0.0f));
}

WorldBox box(glm::vec3 min, glm::vec3 max) { return {min, max}; }

TEST(BatchCulling, ABoxIsOutsideOnlyWhenWhollyBeyondOnePlane) {
  const glm::mat4 view_proj = looking_down_minus_z();
  struct Case {
    const char* what;
    WorldBox box;
    bool outside;
  };
  const Case cases[] = {
      {"in front", box({-1, -1, -11}, {1, 1, -9}), false},
      {"behind the eye", box({-1, -1, 2}, {1, 1, 4}), true},
      {"before the near plane", box({-0.1f, -0.1f, -0.5f}, {0.1f, 0.1f, -0.2f}), true},
      {"beyond the far plane", box({-1, -1, -300}, {1, 1, -200}), true},
      {"left of the frustum", box({-30, -1, -11}, {-20, 1, -9}), true},
      {"above the frustum", box({-1, 20, -11}, {1, 30, -9}), true},
      {"straddling the left plane", box({-15, -1, -11}, {-5, 1, -9}), false},
      {"around the eye", box({-1, -1, -1}, {1, 1, 1}), false},
      {"across the far plane", box({-1, -1, -150}, {1, 1, -50}), false},
      {"empty", empty_world_box(), true},
  };
  for (const Case& c : cases) EXPECT_EQ(outside_clip_volume(view_proj, c.box), c.outside) << c.what;
}

Scene two_cubes() {
  Scene scene;
  Mesh cube;
  for (int i = 0; i < 8; ++i) {
    MeshVertex v{};
    v.position = {(i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? 1.0f : -1.0f};
    cube.vertices.push_back(v);
  }
  scene.meshes = {cube, Mesh{}};  // the second has no vertices
  Instance near{}, far{};
  near.model = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -10));
  far.model = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 10)) * glm::scale(glm::mat4(1.0f), glm::vec3(2.0f));
  scene.instances = {near, far, near};
  scene.batches = {{0, 0, 1}, {0, 1, 1}, {0, 0, 2}, {1, 2, 1}};
  return scene;
}

TEST(BatchCulling, BoundsAreTheUnionOfEachBatchsInstances) {
  const std::vector<WorldBox> bounds = batch_bounds(two_cubes());
  ASSERT_EQ(bounds.size(), 4u);
  EXPECT_EQ(bounds[0].min, glm::vec3(-1, -1, -11));
  EXPECT_EQ(bounds[0].max, glm::vec3(1, 1, -9));
  EXPECT_EQ(bounds[1].min, glm::vec3(-2, -2, 8));
  EXPECT_EQ(bounds[1].max, glm::vec3(2, 2, 12));
  EXPECT_EQ(bounds[2].min, glm::vec3(-2, -2, -11));
  EXPECT_EQ(bounds[2].max, glm::vec3(2, 2, 12));
  EXPECT_TRUE(is_empty(bounds[3]));
}

TEST(BatchCulling, EachPassDrawsWhatItsVolumeMayHoldAndCountsTheRest) {
  const BatchSelection selection = select_batches(batch_bounds(two_cubes()), looking_down_minus_z());
  EXPECT_EQ(selection.drawn, (std::vector<bool>{true, false, true, false}));
  EXPECT_EQ(selection.culled, 2u);
}

}  // namespace
}  // namespace tilelight
