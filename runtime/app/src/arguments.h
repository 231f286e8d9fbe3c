#pragma once
// What the tilelight command line asks for, as parsed (cli.cpp fills it; render_run.cpp acts
// on it). Values are as typed: their meaning and checks live where they are used.

#include <cstdint>
#include <optional>
#include <string>

namespace tilelight::app {

struct Arguments {
  std::uint32_t width = 1280, height = 720, frames = 1, tile_size = 4;
  std::string msaa = "auto";
  std::string path = "cpu";
  std::string permutations = "optimised";
  std::string camera = "default";
  std::string primitive = "auto";
  std::string baseline = "both";
  std::string light_pass = "compute";  // measured faster on lavapipe (docs/results.md g4), the pass for GPUs
  std::string device = "auto";
  std::string out = "tilelight-out";
  std::string scene;  // a glTF file; empty: the procedural scene
  std::optional<std::uint32_t> scene_index;
  bool validation = false;
  bool no_coalesce = false;
  bool list_devices = false;
  bool list_cameras = false;
  double timeout_s = 60.0;
};

}  // namespace tilelight::app
