#include "tilelight/scene/world_box.h"

#include <limits>

namespace tilelight {

WorldBox empty_world_box() {
  return {glm::vec3(std::numeric_limits<float>::max()), glm::vec3(std::numeric_limits<float>::lowest())};
}

bool is_empty(const WorldBox& box) { return box.min.x > box.max.x || box.min.y > box.max.y || box.min.z > box.max.z; }

void add_point(WorldBox& box, const glm::vec3& point) {
  box.min = glm::min(box.min, point);
  box.max = glm::max(box.max, point);
}

std::array<glm::vec3, 8> corners(const WorldBox& box) {
  std::array<glm::vec3, 8> c{};
  for (int i = 0; i < 8; ++i) {
    c[static_cast<std::size_t>(i)] = {(i & 1) != 0 ? box.max.x : box.min.x, (i & 2) != 0 ? box.max.y : box.min.y,
                                      (i & 4) != 0 ? box.max.z : box.min.z};
  }
  return c;
}

}  // namespace tilelight
