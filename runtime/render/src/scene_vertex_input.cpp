#include "scene_vertex_input.h"

#include "tilelight/scene/scene.h"

#include <cstddef>

namespace tilelight {

std::vector<VkVertexInputBindingDescription> scene_vertex_bindings() {
  return {{0, sizeof(MeshVertex), VK_VERTEX_INPUT_RATE_VERTEX}, {1, sizeof(Instance), VK_VERTEX_INPUT_RATE_INSTANCE}};
}

std::vector<VkVertexInputAttributeDescription> scene_vertex_attributes() {
  std::vector<VkVertexInputAttributeDescription> a{{0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(MeshVertex, position)},
                                                   {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(MeshVertex, normal)},
                                                   {8, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(MeshVertex, uv)}};
  for (std::uint32_t column = 0; column < 4; ++column) {
    a.push_back({2 + column, 1, VK_FORMAT_R32G32B32A32_SFLOAT,
                 static_cast<std::uint32_t>(offsetof(Instance, model) + column * sizeof(glm::vec4))});
  }
  a.push_back({6, 1, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(Instance, albedo_spec)});
  a.push_back({7, 1, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(Instance, material)});
  a.push_back({9, 1, VK_FORMAT_R32G32_SFLOAT, offsetof(Instance, alpha_mask)});
  return a;
}

std::vector<VkVertexInputAttributeDescription> shadow_caster_attributes(bool masked) {
  std::vector<VkVertexInputAttributeDescription> kept;
  for (const VkVertexInputAttributeDescription& a : scene_vertex_attributes()) {
    const bool position_or_model = a.location == 0 || (a.location >= 2 && a.location <= 5);
    if (position_or_model || (masked && a.location >= 8)) kept.push_back(a);
  }
  return kept;
}

}  // namespace tilelight
