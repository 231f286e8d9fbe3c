#pragma once
// The file's KHR_lights_punctual lights in the renderer's world (docs/scene-input.md, "Local
// lights"): every node of the drawn scene that references a light places one, at the node's
// world origin, pointing down its -z, moved and scaled with the meshes (Scene::world_from_file).
//   - point and spot lights, and directional ones with extras.tilelight_box, become
//     Scene::local_lights;
//   - the first directional light without a box becomes the sun (its direction and colour; the
//     command line's --sun-direction still overrides the direction); later ones are warned about.
//
// Units: one unit of the sun's scale (SunAndAtmosphere::sun_color, LocalLight::intensity) is
// kLuxPerSunUnit lux. Candela become intensities at 1 m of the file, times the framing's scale
// squared, so that colour * intensity / d^2 in the renderer's metres equals the file's
// candela / d^2 in its own: the lit result looks the same at any scale.

#include "base_colour_textures.h"
#include "gltf_light_json.h"
#include "tilelight/scene/scene.h"
#include "tinygltf.h"

#include <string>
#include <vector>

namespace tilelight::gltf_detail {

// The exposure: lux per unit of the sun's scale. 1, as the Khronos glTF Sample Viewer and
// three.js show a file's lights at exposure 1, so a file looks as its author saw it there (the
// demo sun is then about 1.5 lux; docs/scene-input.md says more).
inline constexpr double kLuxPerSunUnit = 1.0;

// A light with no range ends where its illuminance, on a surface facing it, falls below this
// fraction of what a surface facing the sun receives (the brightest channels of both): about
// one step of an 8-bit channel at the sun's brightness.
inline constexpr double kRangeBoundFractionOfSun = 1.0 / 256.0;

// Bounds on that distance, in the renderer's metres: a light of no intensity still has a volume,
// and a very bright one needs none larger than the 10 m scene seen from 1 km.
inline constexpr float kMinBoundedRange = 0.01f;
inline constexpr float kMaxBoundedRange = 1000.0f;

// Places `lights` in `scene` (see above); `textures` decodes the globe maps, so it must not have
// given its textures away yet. Preconditions: place_meshes() accepted scenes[scene_index]'s
// node graph, and fit_scene() has run. Throws tilelight::Error naming the element at fault
// (a globe texture that does not exist, a light whose node collapses its -z axis, a value that
// overflows once scaled). Returns warning lines (without "warning: FILE: "): the lights loaded
// but not yet drawn, directional lights beyond the first.
std::vector<std::string> add_file_lights(const tinygltf::Model& model, std::size_t scene_index,
                                         const FileLights& lights, BaseColourTextures& textures, Scene& scene);

}  // namespace tilelight::gltf_detail
