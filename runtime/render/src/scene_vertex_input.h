#pragma once
// How the scene's meshes and instances reach a vertex shader: binding 0 the mesh's vertices
// (MeshVertex), binding 1 its instances (Instance), at the locations uber/scene/scene.vert
// declares. The scene passes (G-buffer, shadow maps) and the forward pass bind the same buffers
// the same way.

#include <vulkan/vulkan.h>

#include <vector>

namespace tilelight {

std::vector<VkVertexInputBindingDescription> scene_vertex_bindings();
// Every attribute: position 0, normal 1, model matrix 2..5, albedo and specular 6, material 7,
// uv 8, alpha mask 9.
std::vector<VkVertexInputAttributeDescription> scene_vertex_attributes();
// What a shadow caster's vertex shader reads (uber/scene/shadow.vert, uber/local_shadow_caster.vert):
// the position and the model matrix, and for an alpha-masked mesh its uv and alpha mask. A
// pipeline gets only the attributes its shader reads (unused ones are a validation performance
// warning).
std::vector<VkVertexInputAttributeDescription> shadow_caster_attributes(bool masked);

}  // namespace tilelight
