#include "gltf_lights.h"

#include "node_graph.h"
#include "tilelight/base/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace tilelight::gltf_detail {
namespace {

// A node of the drawn scene that references a light, with its transform in the file.
struct PlacedLight {
  int node = 0;
  int light = 0;
  glm::mat4 world{1.0f};
};

// The scene's nodes that reference a light, depth first in the file's order (place_meshes()'s
// order), so "the first directional light" is the first one a reader of the file meets.
std::vector<PlacedLight> place_lights(const tinygltf::Model& model, std::size_t scene_index,
                                      const std::vector<int>& light_of_node) {
  struct Pending {
    int node;
    glm::mat4 parent_world;
  };
  std::vector<Pending> stack;
  const std::vector<int>& roots = model.scenes[scene_index].nodes;
  for (auto root = roots.rbegin(); root != roots.rend(); ++root) stack.push_back({*root, glm::mat4(1.0f)});
  std::vector<PlacedLight> placed;
  while (!stack.empty()) {
    const Pending next = stack.back();
    stack.pop_back();
    const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(next.node)];
    const glm::mat4 world = next.parent_world * local_transform(node, next.node);
    const auto index = static_cast<std::size_t>(next.node);
    if (index < light_of_node.size() && light_of_node[index] >= 0) {
      placed.push_back({next.node, light_of_node[index], world});
    }
    for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) stack.push_back({*child, world});
  }
  return placed;
}

std::string light_path(int light) { return fmt::format("extensions.KHR_lights_punctual.lights[{}]", light); }

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The node's -z in the renderer's world, normalised.
glm::vec3 direction_of(const glm::mat4& world, int node) {
  const glm::vec3 axis(world * glm::vec4(0.0f, 0.0f, -1.0f, 0.0f));
  const glm::vec3 direction = glm::normalize(axis);
  if (!finite(direction) || !(glm::length(axis) > 0.0f)) {
    throw Error(fmt::format("nodes[{}]: its transform collapses the -z axis its light points along", node));
  }
  return direction;
}

float max_channel(const glm::vec3& c) { return std::max({c.x, c.y, c.z}); }

// A value converted to the renderer's units, checked to stay finite.
float scaled(double value, double factor, int light, const char* property) {
  const auto v = static_cast<float>(value * factor);
  if (!std::isfinite(v)) {
    throw Error(
        fmt::format("{}.{}: {} is too large once the scene is scaled to metres", light_path(light), property, value));
  }
  return v;
}

// An undefined range: where colour * intensity / d^2 falls to kRangeBoundFractionOfSun of the sun.
float bounded_range(const LocalLight& light, const SunAndAtmosphere& sun) {
  const double sun_peak = max_channel(sun.sun_color);
  if (!(sun_peak > 0.0)) return kMaxBoundedRange;  // no sun to compare with
  const double d = std::sqrt(max_channel(light.color) * light.intensity / (kRangeBoundFractionOfSun * sun_peak));
  return std::clamp(static_cast<float>(d), kMinBoundedRange, kMaxBoundedRange);
}

LocalLight local_light(const FileLight& source, const PlacedLight& at, const Scene& scene,
                       BaseColourTextures& textures) {
  const glm::mat4 world = scene.world_from_file * at.world;
  const double scale = glm::length(glm::vec3(scene.world_from_file[0]));
  LocalLight light;
  light.position = glm::vec3(world * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  if (!finite(light.position)) throw Error(fmt::format("nodes[{}]: its light's position is not finite", at.node));
  // A point light has no direction: a node that flattens its -z still places it.
  if (source.kind != FileLightKind::point) light.direction = direction_of(world, at.node);
  light.color = source.color;
  light.casts_shadows = source.casts_shadows;
  light.extras.back_color = source.back_color;
  if (source.globe_texture) {
    light.extras.globe_texture =
        textures.of_texture(*source.globe_texture, light_path(at.light) + ".extras.tilelight_globe");
  }
  if (source.kind == FileLightKind::box) {
    light.type = LocalLightType::box;
    light.intensity = scaled(source.intensity, 1.0 / kLuxPerSunUnit, at.light, "intensity");  // lux: no distance
    light.box_half_extent = source.box_half_extent * static_cast<float>(scale);
    light.box_falloff = scaled(source.box_falloff, scale, at.light, "extras.tilelight_box.falloff");
    if (!finite(light.box_half_extent)) {
      throw Error(light_path(at.light) + ".extras.tilelight_box.half_extent: too large once the scene is scaled");
    }
    return light;
  }
  light.type = source.kind == FileLightKind::spot ? LocalLightType::spot : LocalLightType::point;
  // Candela at the file's 1 m: times scale^2 at the renderer's, so that intensity / d^2 is kept.
  light.intensity = scaled(source.intensity, scale * scale / kLuxPerSunUnit, at.light, "intensity");
  light.range = source.range ? scaled(*source.range, scale, at.light, "range") : bounded_range(light, scene.sun);
  if (!(light.range > 0.0f)) light.range = kMinBoundedRange;  // a range that underflowed once scaled
  light.inner_cone_cos = static_cast<float>(std::cos(source.inner_cone));
  light.outer_cone_cos = static_cast<float>(std::cos(source.outer_cone));
  return light;
}

// The first directional light (no box) becomes the sun; the count of the others.
std::size_t place_sun(const FileLights& lights, const std::vector<PlacedLight>& placed, Scene& scene) {
  std::size_t directional = 0;
  for (const PlacedLight& at : placed) {
    const FileLight& source = lights.lights[static_cast<std::size_t>(at.light)];
    if (source.kind != FileLightKind::directional) continue;
    if (directional++ > 0) continue;
    // The sun's direction points towards it: against the light's travel.
    scene.sun.sun_direction = -direction_of(scene.world_from_file * at.world, at.node);
    scene.sun.sun_color = source.color * scaled(source.intensity, 1.0 / kLuxPerSunUnit, at.light, "intensity");
  }
  return directional > 0 ? directional - 1 : 0;
}

}  // namespace

std::vector<std::string> add_file_lights(const tinygltf::Model& model, std::size_t scene_index,
                                         const FileLights& lights, BaseColourTextures& textures, Scene& scene) {
  const std::vector<PlacedLight> placed = place_lights(model, scene_index, lights.light_of_node);
  std::vector<std::string> warnings;
  // The sun first: undefined ranges are bounded against it.
  if (const std::size_t ignored = place_sun(lights, placed, scene); ignored > 0) {
    warnings.push_back(
        fmt::format("{} more directional light{} ignored: the first one is the sun, and there is one sun", ignored,
                    ignored == 1 ? "" : "s"));
  }
  for (const PlacedLight& at : placed) {
    const FileLight& source = lights.lights[static_cast<std::size_t>(at.light)];
    if (source.kind == FileLightKind::directional) continue;
    scene.local_lights.push_back(local_light(source, at, scene, textures));
  }
  return warnings;
}

}  // namespace tilelight::gltf_detail
