#include "node_graph.h"

#include "tilelight/base/error.h"

#include <fmt/format.h>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <tuple>

namespace tilelight::gltf_detail {
namespace {

std::string node_name(int index) { return fmt::format("nodes[{}]", index); }

bool all_finite(const std::vector<double>& values) {
  for (double v : values) {
    if (!std::isfinite(v) || std::fabs(v) > std::numeric_limits<float>::max()) return false;
  }
  return true;
}

bool finite(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      if (!std::isfinite(m[c][r])) return false;
    }
  }
  return true;
}

// Every child reference in range and each node the child of at most one parent.
std::vector<int> parents_of(const tinygltf::Model& model) {
  std::vector<int> parent(model.nodes.size(), -1);
  for (std::size_t n = 0; n < model.nodes.size(); ++n) {
    for (int child : model.nodes[n].children) {
      if (child < 0 || static_cast<std::size_t>(child) >= model.nodes.size()) {
        throw Error(fmt::format("{}.children: node {} does not exist (the file has {})", node_name(static_cast<int>(n)),
                                child, model.nodes.size()));
      }
      if (parent[static_cast<std::size_t>(child)] != -1) {
        throw Error(fmt::format("{} is a child of both {} and {} (glTF nodes form strict trees)", node_name(child),
                                node_name(parent[static_cast<std::size_t>(child)]), node_name(static_cast<int>(n))));
      }
      parent[static_cast<std::size_t>(child)] = static_cast<int>(n);
    }
  }
  return parent;
}

// The chain "nodes[a] -> nodes[b] -> ... -> nodes[a]" that closes a cycle at `node`.
std::string cycle_text(const std::vector<int>& parent, int node) {
  std::vector<int> chain{node};
  for (int n = parent[static_cast<std::size_t>(node)]; n != node && n != -1 && chain.size() <= parent.size();
       n = parent[static_cast<std::size_t>(n)]) {
    chain.push_back(n);
  }
  std::string text = node_name(node);
  for (auto it = chain.rbegin(); it != chain.rend(); ++it) text += " -> " + node_name(*it);
  return text;
}

// A scene's root must have no parent; if following its parents leads back to it, the nodes form
// a cycle (a node of a cycle, every one with a parent, is the only way to find one from a scene).
void check_root(const std::vector<int>& parent, std::size_t scene_index, int root) {
  if (parent[static_cast<std::size_t>(root)] == -1) return;
  int n = parent[static_cast<std::size_t>(root)];
  for (std::size_t steps = 0; n != -1 && n != root && steps < parent.size(); ++steps)
    n = parent[static_cast<std::size_t>(n)];
  if (n == root) throw Error("the node hierarchy has a cycle: " + cycle_text(parent, root));
  throw Error(fmt::format("scenes[{}].nodes: {} is a root of the scene but also a child of {}", scene_index,
                          node_name(root), node_name(parent[static_cast<std::size_t>(root)])));
}

}  // namespace

glm::mat4 local_transform(const tinygltf::Node& node, int index) {
  const std::string name = node_name(index);
  for (const auto& [property, values, length] :
       {std::tuple{"matrix", &node.matrix, std::size_t{16}},
        std::tuple{"translation", &node.translation, std::size_t{3}},
        std::tuple{"rotation", &node.rotation, std::size_t{4}}, std::tuple{"scale", &node.scale, std::size_t{3}}}) {
    if (!values->empty() && values->size() != length) {
      throw Error(fmt::format("{}.{}: expected {} numbers, got {}", name, property, length, values->size()));
    }
    if (!all_finite(*values)) throw Error(fmt::format("{}.{}: not every number is finite", name, property));
  }
  if (!node.matrix.empty()) {
    glm::mat4 m(1.0f);
    for (int column = 0; column < 4; ++column) {
      for (int row = 0; row < 4; ++row)
        m[column][row] =
            static_cast<float>(node.matrix[static_cast<std::size_t>(column) * 4 + static_cast<std::size_t>(row)]);
    }
    return m;
  }
  glm::mat4 m(1.0f);
  if (!node.translation.empty()) {
    m[3] = glm::vec4(static_cast<float>(node.translation[0]), static_cast<float>(node.translation[1]),
                     static_cast<float>(node.translation[2]), 1.0f);
  }
  if (!node.rotation.empty()) {
    // glTF stores x, y, z, w; glm::quat's constructor takes w first.
    glm::quat q(static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]),
                static_cast<float>(node.rotation[1]), static_cast<float>(node.rotation[2]));
    const float length = glm::length(q);
    if (!(length > 0.0f) || !std::isfinite(length)) throw Error(name + ".rotation: not a rotation (zero quaternion)");
    m = m * glm::mat4_cast(q / length);
  }
  if (!node.scale.empty()) {
    m = m * glm::mat4(glm::vec4(static_cast<float>(node.scale[0]), 0, 0, 0),
                      glm::vec4(0, static_cast<float>(node.scale[1]), 0, 0),
                      glm::vec4(0, 0, static_cast<float>(node.scale[2]), 0), glm::vec4(0, 0, 0, 1));
  }
  return m;
}

std::vector<PlacedMesh> place_meshes(const tinygltf::Model& model, std::size_t scene_index) {
  const std::vector<int> parent = parents_of(model);
  const tinygltf::Scene& scene = model.scenes[scene_index];
  // Iterative depth-first walk: a deep chain of nodes must not exhaust the stack.
  std::vector<bool> visited(model.nodes.size(), false);
  std::vector<PlacedMesh> placed;
  struct Pending {
    int node;
    glm::mat4 parent_world;
  };
  std::vector<Pending> stack;
  for (auto root = scene.nodes.rbegin(); root != scene.nodes.rend(); ++root) {
    if (*root < 0 || static_cast<std::size_t>(*root) >= model.nodes.size()) {
      throw Error(fmt::format("scenes[{}].nodes: node {} does not exist (the file has {})", scene_index, *root,
                              model.nodes.size()));
    }
    check_root(parent, scene_index, *root);
    stack.push_back({*root, glm::mat4(1.0f)});
  }
  while (!stack.empty()) {
    const Pending next = stack.back();
    stack.pop_back();
    const auto index = static_cast<std::size_t>(next.node);
    // Roots have no parent and every other node one, so only a root listed twice comes back.
    if (visited[index]) throw Error(fmt::format("scenes[{}].nodes lists {} twice", scene_index, node_name(next.node)));
    visited[index] = true;
    const tinygltf::Node& node = model.nodes[index];
    const glm::mat4 world = next.parent_world * local_transform(node, next.node);
    if (!finite(world)) throw Error(node_name(next.node) + ": its world transform is not finite");
    if (node.mesh >= 0) {
      if (static_cast<std::size_t>(node.mesh) >= model.meshes.size()) {
        throw Error(fmt::format("{}.mesh: mesh {} does not exist (the file has {})", node_name(next.node), node.mesh,
                                model.meshes.size()));
      }
      placed.push_back({next.node, node.mesh, world});
    }
    for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) stack.push_back({*child, world});
  }
  return placed;
}

}  // namespace tilelight::gltf_detail
