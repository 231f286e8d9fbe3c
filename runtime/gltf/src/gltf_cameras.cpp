#include "gltf_cameras.h"

#include "node_graph.h"
#include "scene_framing.h"
#include "tilelight/base/error.h"
#include "tilelight/scene/view_fit.h"

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace tilelight::gltf_detail {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The first node of the file whose "camera" is `camera`, or -1.
int first_node_of(const tinygltf::Model& model, int camera) {
  for (std::size_t n = 0; n < model.nodes.size(); ++n) {
    if (model.nodes[n].camera == camera) return static_cast<int>(n);
  }
  return -1;
}

// The node's world transform through its parents, or nullopt where its ancestry is no tree
// (a node outside the drawn scene is not checked by place_meshes()).
std::optional<glm::mat4> world_of(const tinygltf::Model& model, int node) {
  std::vector<int> parent(model.nodes.size(), -1);
  for (std::size_t n = 0; n < model.nodes.size(); ++n) {
    for (int child : model.nodes[n].children) {
      if (child >= 0 && static_cast<std::size_t>(child) < parent.size())
        parent[static_cast<std::size_t>(child)] = static_cast<int>(n);
    }
  }
  glm::mat4 world(1.0f);
  std::size_t steps = 0;
  for (int n = node; n != -1; n = parent[static_cast<std::size_t>(n)]) {
    if (++steps > model.nodes.size()) return std::nullopt;  // a cycle
    world = local_transform(model.nodes[static_cast<std::size_t>(n)], n) * world;
  }
  return world;
}

// Why a perspective camera cannot be drawn, or "".
std::string perspective_problem(const tinygltf::PerspectiveCamera& p) {
  if (!std::isfinite(p.yfov) || !(p.yfov > 0.0) || !(p.yfov < kPi)) {
    return fmt::format("perspective.yfov {} is not an angle between 0 and pi radians", p.yfov);
  }
  if (!std::isfinite(p.znear) || !(p.znear > 0.0)) return fmt::format("perspective.znear {} is not positive", p.znear);
  if (!std::isfinite(p.zfar) || (p.zfar != 0.0 && !(p.zfar > p.znear))) {
    return fmt::format("perspective.zfar {} is not beyond znear {}", p.zfar, p.znear);
  }
  return "";
}

Camera file_camera(const tinygltf::Model& model, int index, const Scene& scene, const WorldBox& box) {
  const tinygltf::Camera& source = model.cameras[static_cast<std::size_t>(index)];
  Camera camera;
  camera.name = fmt::format("gltf:{}", index);
  const std::string label = fmt::format("cameras[{}]", index) + (source.name.empty() ? "" : " \"" + source.name + "\"");
  camera.description = label;
  const int node = first_node_of(model, index);
  std::string problem;
  std::optional<glm::mat4> placed;
  if (source.type != "perspective") problem = source.type + ", and only perspective cameras are drawn";
  if (problem.empty()) problem = perspective_problem(source.perspective);
  if (problem.empty() && node < 0) problem = "no node references it, so it has no place";
  if (problem.empty()) {
    try {
      placed = world_of(model, node);
      if (!placed) problem = fmt::format("nodes[{}] is in a cycle of nodes", node);
    } catch (const Error& e) {
      problem = e.what();
    }
  }
  if (!problem.empty()) {
    camera.unusable = label + ": " + problem;
    camera.description += " (not usable: " + problem + ")";
    return camera;
  }
  // glTF cameras look down their node's -z with +y up; the scene's placement scales uniformly.
  const glm::mat4 world = scene.world_from_file * *placed;
  const float scale = glm::length(glm::vec3(scene.world_from_file[0]));
  camera.position = glm::vec3(world * glm::vec4(0, 0, 0, 1));
  camera.target = camera.position + glm::normalize(glm::vec3(world * glm::vec4(0, 0, -1, 0)));
  camera.up = glm::normalize(glm::vec3(world * glm::vec4(0, 1, 0, 0)));
  camera.vertical_fov_degrees = static_cast<float>(source.perspective.yfov * 180.0 / kPi);
  fit_clip_planes(camera, box);
  camera.near_plane = static_cast<float>(source.perspective.znear) * scale;
  if (source.perspective.zfar > 0.0) camera.far_plane = static_cast<float>(source.perspective.zfar) * scale;
  camera.description +=
      fmt::format(" placed by nodes[{}], vertical field of view {:.1f} degrees", node, camera.vertical_fov_degrees);
  return camera;
}

}  // namespace

void add_file_cameras(const tinygltf::Model& model, Scene& scene) {
  if (model.cameras.empty()) return;
  // fit_scene() placed the scene inside this box: no pass over the vertices needed.
  const WorldBox box{glm::vec3(-kSceneRadius), glm::vec3(kSceneRadius)};
  for (std::size_t c = 0; c < model.cameras.size(); ++c) {
    scene.cameras.push_back(file_camera(model, static_cast<int>(c), scene, box));
  }
}

}  // namespace tilelight::gltf_detail
