#pragma once
// KHR_lights_punctual as the file states it: the top-level "lights" and the nodes that reference
// them, read from the JSON (tinygltf 2.7 keeps no node -> light reference and reads a range of 0
// as "infinite"), every value checked, with this renderer's own "extras" on a light (box lights,
// back colours, globe maps; docs/scene-input.md, "Local lights"). Nothing is placed or converted
// to the renderer's units here: gltf_lights.h does that.

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <optional>
#include <vector>

namespace tilelight::gltf_detail {

// glTF's spot cone defaults (KHR_lights_punctual: innerConeAngle 0, outerConeAngle pi/4).
inline constexpr double kDefaultInnerConeAngle = 0.0;
inline constexpr double kDefaultOuterConeAngle = 0.78539816339744830962;

// A directional light with extras.tilelight_box is a box light: its light confined to a box.
enum class FileLightKind { point, spot, directional, box };

struct FileLight {
  FileLightKind kind = FileLightKind::point;
  glm::vec3 color{1.0f};                       // linear RGB, each >= 0
  double intensity = 1.0;                      // >= 0: candela (point, spot) or lux (directional, box)
  std::optional<double> range;                 // > 0, in the file's units; none: infinite
  double inner_cone = kDefaultInnerConeAngle;  // radians, 0 <= inner < outer
  double outer_cone = kDefaultOuterConeAngle;  // radians, 0 < outer <= pi/2
  glm::vec3 box_half_extent{1.0f};             // box: each > 0, in the file's units
  double box_falloff = 0.0;                    // box: 0 < falloff <= the smallest half extent
  std::optional<glm::vec3> back_color;         // box only
  std::optional<int> globe_texture;            // a glTF texture index (not checked against "textures" here)
  bool casts_shadows = true;
};

struct FileLights {
  std::vector<FileLight> lights;
  std::vector<int> light_of_node;  // per node of the file: an index into `lights`, or -1
};

// Reads the lights and the nodes' references to them from `root` (a document that
// check_json_schema() accepted). Throws tilelight::Error naming the element at fault, without the
// file's name: "extensions.KHR_lights_punctual.lights[2].spot.outerConeAngle: ...",
// "nodes[3].extensions.KHR_lights_punctual.light: light 5 does not exist (the file has 2)".
FileLights read_file_lights(const nlohmann::json& root);

}  // namespace tilelight::gltf_detail
