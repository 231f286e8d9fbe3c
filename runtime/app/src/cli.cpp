#include "tilelight/app/cli.h"

#include "arguments.h"
#include "option_names.h"
#include "render_run.h"
#include "tilelight/app/camera_choice.h"
#include "tilelight/app/failure.h"
#include "tilelight/app/usage_error.h"
#include "tilelight/scene/local_light_placement.h"

#include <command_line/command_line.h>
#include <CLI/CLI.hpp>

#include <string>

namespace tilelight::app {
namespace {

// A CLI11 transform from the names in `names` to their values (as CLI11 then reads them into
// the option's variable): anything else is a usage error naming the flag, "--flag: x not in
// {a,b}", as CLI::IsMember words it.
template <typename T>
CLI::Validator one_of(const OptionNames<T>& names) {
  std::string choices = "{";
  for (const auto& [name, value] : names) choices += (choices.size() > 1 ? "," : "") + name;
  choices += "}";
  return CLI::Validator(
      [&names, choices](std::string& input) {
        for (const auto& [name, value] : names) {
          if (input == name) {
            input = std::to_string(static_cast<long long>(value));
            return std::string();
          }
        }
        return input + " not in " + choices;
      },
      choices);
}

// Adds --`flag`, parsed through `names` into `value`, whose initial value is the default shown.
template <typename T>
CLI::Option* add_choice(CLI::App& cli, const std::string& flag, T& value, const OptionNames<T>& names,
                        const std::string& help) {
  return cli.add_option(flag, value, help)
      ->transform(one_of(names))
      ->type_name("TEXT")  // what is typed; CLI11 would name the variable's type
      ->default_str(name_of(names, value));
}

// --lights: the procedural scene's street lamps (a --scene file brings its own).
void add_light_options(CLI::App& cli, Arguments& a) {
  cli.add_option("--lights", a.lights,
                 "local lights the procedural scene places along its streets, point, spot and box in turn "
                 "(default 0); a --scene file is lit by its own KHR_lights_punctual lights")
      ->type_name("N")
      ->check(CLI::Range(0u, kMaxDemoLights));
}

void add_options(CLI::App& cli, Arguments& a) {
  cli.add_option("--width", a.width, "frame width in pixels")->capture_default_str();
  cli.add_option("--height", a.height, "frame height in pixels")->capture_default_str();
  add_choice(cli, "--msaa", a.msaa, msaa_names(),
             "G-buffer samples: auto (2 where offered, else 4), 1 (no MSAA: single-sampled G-buffer), 2, 4, 8, 16");
  add_choice(cli, "--path", a.path, path_names(),
             "index build: cpu (host patches pre-recorded draws) or gpu (compute)");
  add_choice(cli, "--permutations", a.raw_permutations, permutation_names(),
             "lighting shaders: optimised (32) or raw (96 of 128)");
  cli.add_option("--camera", a.view.camera,
                 "camera: default, sky, shadow, low, street, closeup (the procedural scene's), or default and "
                 "gltf:N (the N-th camera of a --scene file); --list-cameras lists them")
      ->capture_default_str();
  add_camera_options(cli, a.view);
  CLI::Option* scene =
      cli.add_option("--scene", a.scene,
                     "a glTF 2.0 file (.gltf or .glb) to render instead of the procedural scene (cameras: default, the "
                     "file's gltf:N, or --eye)");
  cli.add_option("--scene-index", a.scene_index, "which scene of the --scene file (default: the file's own choice)")
      ->needs(scene);
  add_light_options(cli, a);
  cli.add_option("--frames", a.frames, "timed frames (after one warm-up frame); timings are medians over them")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cli.add_option("--tile-size", a.tile_size, "tile size in pixels: 4, 8 or 16")
      ->check(CLI::IsMember({4u, 8u, 16u}))
      ->capture_default_str();
  cli.add_flag("--no-coalesce", a.no_coalesce, "one rectangle per tile (no tile coalescing)");
  cli.add_flag("--no-cull", a.no_cull,
               "draw every mesh batch in the G-buffer and shadow passes (default: skip those wholly outside the "
               "camera's or the sun's view; report.json counts them under culled)");
  cli.add_option("--primitive", a.primitive,
                 "tile pass primitive: points (a point sprite per square of tiles), triangles (two per "
                 "rectangle), auto (points where the device draws them)")
      ->check(CLI::IsMember({"auto", "points", "triangles"}))
      ->capture_default_str();
  add_choice(cli, "--baseline", a.baseline, baseline_names(),
             "full-frame passes timed against the classified frame, each after a plain G-buffer pass: naive (every "
             "feature on every sample), dynamic (one pass branching per pixel), floor (reads the G-buffer, no "
             "lighting: what any full-frame light pass costs at least), both (naive and dynamic), all, none");
  add_choice(cli, "--light-pass", a.light_pass, light_pass_names(),
             "how the light passes run: raster (the tile pass draws each class's tiles) or compute (one "
             "indirect dispatch per class over its tile list); the baselines run as the same kind");
  add_choice(cli, "--light-kinds", a.light_kinds, light_kinds_names(),
             "how the light domain's SKY and LIGHT_SCATTERING features reach the tile pass: variant (compiled "
             "into the 32 permutations), specialization (constants fixed per pipeline) or branch (read per draw "
             "from a uniform block); the same frame, the baselines always the variant build");
  add_choice(cli, "--local-light-pass", a.local_light_pass, local_light_pass_names(),
             "how the scene's local lights are added: volumes (each light's sphere, cone or box, depth- and "
             "stencil-tested) or fullscreen (one full-screen pass per light: the reference)");
  add_choice(cli, "--local-light-shadows", a.local_light_shadows, on_off_names(),
             "shadow maps for the local lights that cast shadows: on or off (every light unshadowed)");
  add_choice(cli, "--local-light-shadow-cache", a.local_light_shadow_cache, on_off_names(),
             "on: the local lights' shadow maps are rendered once and kept (the scene is static); off: rendered "
             "again every frame (timings_ms.local_light_shadows)");
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
    return render_run(arguments, out, err, stage);
  } catch (const UsageError& e) {
    // Flags that parse but do not fit the scene or each other: worded and counted as CLI11's.
    err << e.what() << "\nRun with --help for more information.\n";
    return command_line::kExitUsage;
  } catch (...) {
    err << "tilelight: error: " << failure_message(stage, std::current_exception()) << '\n';
    return command_line::kExitError;
  }
}

}  // namespace tilelight::app
