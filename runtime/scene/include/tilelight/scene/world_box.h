#pragma once
// An axis-aligned box in the renderer's world: the bounds the view fit (view_fit.h) and batch
// culling (batch_culling.h) work with.

#include <glm/glm.hpp>

#include <array>

namespace tilelight {

struct WorldBox {
  glm::vec3 min{0.0f}, max{0.0f};
};

// A box that holds nothing yet (min above max): add_point() makes it the point's.
WorldBox empty_world_box();
bool is_empty(const WorldBox& box);
void add_point(WorldBox& box, const glm::vec3& point);

// Corner i has x from max where bit 0 of i is set (else min), y by bit 1, z by bit 2.
std::array<glm::vec3, 8> corners(const WorldBox& box);

}  // namespace tilelight
