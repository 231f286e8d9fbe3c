#include "tilelight/app/cli.h"

#include "arguments.h"
#include "render_run.h"
#include "tilelight/app/failure.h"

#include <command_line/command_line.h>
#include <CLI/CLI.hpp>

namespace tilelight::app {
namespace {

void add_options(CLI::App& cli, Arguments& a) {
  cli.add_option("--width", a.width, "frame width in pixels")->capture_default_str();
  cli.add_option("--height", a.height, "frame height in pixels")->capture_default_str();
  cli.add_option("--msaa", a.msaa,
                 "G-buffer samples: auto (2 where offered, else 4), 1 (no MSAA: single-sampled G-buffer), 2, 4, 8, 16")
      ->capture_default_str();
  cli.add_option("--path", a.path, "index build: cpu (host patches pre-recorded draws) or gpu (compute)")
      ->check(CLI::IsMember({"cpu", "gpu"}))
      ->capture_default_str();
  cli.add_option("--permutations", a.permutations, "lighting shaders: optimised (32) or raw (96 of 128)")
      ->check(CLI::IsMember({"optimised", "raw"}))
      ->capture_default_str();
  cli.add_option("--camera", a.camera, "camera: default, sky, shadow, low, street, closeup (--list-cameras)")
      ->capture_default_str();
  CLI::Option* scene =
      cli.add_option("--scene", a.scene,
                     "a glTF 2.0 file (.gltf or .glb) to render instead of the procedural scene (camera: default)");
  cli.add_option("--scene-index", a.scene_index, "which scene of the --scene file (default: the file's own choice)")
      ->needs(scene);
  cli.add_option("--frames", a.frames, "timed frames (after one warm-up frame); timings are medians over them")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cli.add_option("--tile-size", a.tile_size, "tile size in pixels: 4, 8 or 16")
      ->check(CLI::IsMember({4u, 8u, 16u}))
      ->capture_default_str();
  cli.add_flag("--no-coalesce", a.no_coalesce, "one rectangle per tile (no tile coalescing)");
  cli.add_option("--primitive", a.primitive,
                 "tile pass primitive: points (a point sprite per square of tiles), triangles (two per "
                 "rectangle), auto (points where the device draws them)")
      ->check(CLI::IsMember({"auto", "points", "triangles"}))
      ->capture_default_str();
  cli.add_option("--baseline", a.baseline,
                 "full-screen passes timed against the classified one: naive (every feature on every pixel), "
                 "dynamic (one pass branching per pixel), both")
      ->check(CLI::IsMember({"naive", "dynamic", "both"}))
      ->capture_default_str();
  cli.add_option("--light-pass", a.light_pass,
                 "how the light passes run: raster (the tile pass draws each class's tiles) or compute (one "
                 "indirect dispatch per class over its tile list); the baselines run as the same kind")
      ->check(CLI::IsMember({"raster", "compute"}))
      ->capture_default_str();
  cli.add_option("--device", a.device,
                 "Vulkan device: auto (a discrete GPU, else an integrated one, else lavapipe), an index or a "
                 "name substring (llvmpipe: lavapipe, the CPU driver)")
      ->capture_default_str();
  cli.add_flag("--validation", a.validation, "enable the Khronos validation layer; any message fails the run");
  cli.add_option("--out", a.out, "output folder")->capture_default_str();
  cli.add_option("--timeout", a.timeout_s, "seconds to wait for the GPU at any one point")->capture_default_str();
  cli.add_flag("--list-devices", a.list_devices, "list the Vulkan devices and exit");
  cli.add_flag("--list-cameras", a.list_cameras, "list the cameras and exit");
}

}  // namespace

int run(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  CLI::App cli(
      "tilelight: tile-classified deferred lighting (Split/Second, GPU Pro 2 ch. 4) on Vulkan.\n"
      "Renders a procedural scene, classifies 4x4 tiles on the GPU, draws each class with its\n"
      "own uber-shader permutation and compares the result with the naive full-screen pass.",
      "tilelight");
  Arguments arguments;
  add_options(cli, arguments);
  const std::vector<std::string> args(argv + (argc > 0 ? 1 : 0), argv + argc);
  if (auto exit_code = command_line::parse(cli, args, out, err)) return *exit_code;
  std::string stage = "starting";
  try {
    return render_run(arguments, out, stage);
  } catch (...) {
    err << "tilelight: error: " << failure_message(stage, std::current_exception()) << '\n';
    return command_line::kExitError;
  }
}

}  // namespace tilelight::app
