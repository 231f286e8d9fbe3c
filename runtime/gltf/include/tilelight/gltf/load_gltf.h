#pragma once
// A glTF 2.0 file (.gltf with external or embedded buffers, or .glb) as the Scene the renderer
// draws: every triangle primitive of one scene of the file, placed by its node transforms,
// coloured by its material's base colour factor and texture, with the demo's sky and sun, a default camera
// framing the scene's bounds from a raised three-quarter view and a shadow map fitted to them.
//
// The file is input like any other: anything wrong with it (not JSON or GLB, a value of the
// wrong JSON type, an index or accessor out of range, a buffer missing or shorter than its
// views, a truncated .glb, non-finite positions, a node graph that is not a set of trees, no
// triangles at all) throws tilelight::Error whose message starts with the file's name and says
// what is wrong and where ("Box.gltf: accessors[2]: ..."). No partial scene is ever returned.
// What the file holds that the renderer ignores (animations, material extensions...) is no
// error: load_gltf() returns one warning line per feature beside the scene. Its
// KHR_lights_punctual lights become Scene::local_lights and the sun (one more warning line while
// the local light passes are not built).
// docs/scene-input.md has the details: what is loaded, what is ignored, the scale, the lights.

#include "tilelight/scene/scene.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace tilelight {

struct GltfLoadOptions {
  // Which of the file's scenes: empty = its "scene" property, else its first scene.
  std::optional<std::uint32_t> scene_index;
};

// A loaded file: the scene, and one line per feature of the file it leaves out, as the
// command line prints them: "warning: FILE: 3 animations ignored: drawn in the rest pose"
// (FILE as errors name it). Empty when nothing is left out.
struct GltfScene {
  Scene scene;
  std::vector<std::string> warnings;
};

// Reads and loads `file`; Scene::source is its file name. External buffers are read relative
// to the file's folder.
GltfScene load_gltf(const std::filesystem::path& file, const GltfLoadOptions& options = {});

// load_gltf(file, options).scene, for callers that report no warnings.
Scene load_gltf_scene(const std::filesystem::path& file, const GltfLoadOptions& options = {});

// The same from bytes in memory (GLB when they start with "glTF", else glTF JSON). `name` starts
// every message and becomes Scene::source. `base_dir`: the folder external buffers are read
// from; empty: no file is read at all and any external buffer is an error (the fuzz target).
GltfScene load_gltf_from_memory(std::span<const std::uint8_t> bytes, const std::string& name,
                                const std::filesystem::path& base_dir, const GltfLoadOptions& options = {});

// load_gltf_from_memory(...).scene.
Scene load_gltf_scene_from_memory(std::span<const std::uint8_t> bytes, const std::string& name,
                                  const std::filesystem::path& base_dir, const GltfLoadOptions& options = {});

}  // namespace tilelight
