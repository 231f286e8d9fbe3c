#pragma once
// A glTF scene's node hierarchy flattened to world transforms. The nodes must form strict
// trees (glTF 2.0, "Nodes and Hierarchy"): every reference in range, no node with two parents,
// no cycle, no scene root that is another node's child. Errors are tilelight::Error naming
// the node ("nodes[1]: ...") without the file.

#include "tinygltf.h"

#include <glm/glm.hpp>

#include <vector>

namespace tilelight::gltf_detail {

struct PlacedMesh {
  int node = 0;
  int mesh = 0;
  glm::mat4 world{1.0f};  // the node's transform times its ancestors'
};

// A node's own transform: its "matrix", else translation * rotation * scale. Throws
// tilelight::Error naming nodes[`index`] when a property has the wrong length or a non-finite
// number, or the rotation is a zero quaternion.
glm::mat4 local_transform(const tinygltf::Node& node, int index);

// Every node of `scene_index` (precondition: a valid index into model.scenes) that has a mesh,
// depth first in the file's order, with its world transform. Each node's local transform is
// its "matrix", else translation * rotation * scale; non-finite ones are errors.
std::vector<PlacedMesh> place_meshes(const tinygltf::Model& model, std::size_t scene_index);

}  // namespace tilelight::gltf_detail
