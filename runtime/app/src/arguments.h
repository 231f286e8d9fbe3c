#pragma once
// What the tilelight command line asks for, as parsed (cli.cpp fills it; render_run.cpp acts
// on it). The choices the renderer takes are parsed to its values once, by the CLI
// (option_names.h); their defaults are RendererOptions' own, so there is one default for each.
// Other values are as typed: their meaning and checks live where they are used.

#include "tilelight/app/camera_choice.h"
#include "tilelight/render/tile_renderer.h"

#include <cstdint>
#include <optional>
#include <string>

namespace tilelight::app {

struct Arguments {
  std::uint32_t width = RendererOptions{}.width, height = RendererOptions{}.height, frames = 1,
                tile_size = RendererOptions{}.tile_size;
  std::uint32_t msaa = RendererOptions{}.msaa;  // 0: auto
  IndexPath path = RendererOptions{}.path;
  bool raw_permutations = RendererOptions{}.raw_permutations;
  CameraRequest view;  // --camera, --eye, ... (camera_choice.h)
  std::string primitive = "auto";
  Baselines baseline = RendererOptions{}.baselines;
  LightPass light_pass = RendererOptions{}.light_pass;
  LightKinds light_kinds = RendererOptions{}.light_kinds;
  LocalLightPass local_light_pass = RendererOptions{}.local_light_pass;
  bool local_light_shadows = RendererOptions{}.local_light_shadows;            // --local-light-shadows
  bool local_light_shadow_cache = RendererOptions{}.local_light_shadow_cache;  // --local-light-shadow-cache
  std::string device = "auto";
  std::string out = "tilelight-out";
  std::string scene;  // a glTF file; empty: the procedural scene
  std::optional<std::uint32_t> scene_index;
  // --lights: local lights placed in the procedural scene (local_light_placement.h); given at all
  // with --scene, even 0, is a usage error (render_run.cpp).
  std::optional<std::uint32_t> lights;
  bool validation = false;
  bool no_coalesce = false;
  bool no_cull = false;
  bool list_devices = false;
  bool list_cameras = false;
  double timeout_s = 60.0;
};

}  // namespace tilelight::app
