#include "tilelight/app/cli.h"

#include "tilelight/app/failure.h"
#include "tilelight/app/output_files.h"
#include "tilelight/app/process_stats.h"
#include "tilelight/app/report.h"
#include "tilelight/gltf/load_gltf.h"
#include "tilelight/picture/png.h"
#include "tilelight/picture/tile_class_image.h"
#include "tilelight/render/tile_renderer.h"
#include "tilelight/scene/scene.h"
#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <split_second_shaders.h>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdlib>
#include <map>
#include <optional>

namespace tilelight::app {
namespace {

constexpr int kExitError = 1;
constexpr int kExitUsage = 2;  // README: 2 on a usage error (CLI11's own codes vary by error kind)

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

std::uint32_t parse_msaa(const std::string& text) {
  if (text == "auto") return 0;
  for (const char* valid : {"1", "2", "4", "8", "16"}) {
    if (text == valid) return static_cast<std::uint32_t>(std::stoul(text));
  }
  throw Error("--msaa " + text + ": expected auto, 1, 2, 4, 8 or 16");
}

Baselines parse_baselines(const std::string& text) {
  if (text == "naive") return Baselines::naive;
  if (text == "dynamic") return Baselines::dynamic;
  return Baselines::both;
}

// The light targets hold linear radiance; the PNGs get the usual display encoding (gamma 2.2
// after clamping to 0..1), so they look as a renderer's output would.
RgbaImage display_encoded(const RgbaImage& linear) {
  RgbaImage out = linear;
  for (std::size_t i = 0; i < out.pixels.size(); ++i) {
    if (i % 4 == 3) continue;
    const float v = std::isnan(out.pixels[i]) ? 0.0f : std::clamp(out.pixels[i], 0.0f, 1.0f);
    out.pixels[i] = std::pow(v, 1.0f / 2.2f);
  }
  return out;
}

std::vector<std::uint8_t> optimised_ids(const std::vector<std::uint8_t>& raw_ids) {
  std::vector<std::uint8_t> out(raw_ids.size());
  for (std::size_t i = 0; i < raw_ids.size(); ++i) {
    out[i] = raw_ids[i] < split_second::kRawCount ? split_second::kRawToOptimised[raw_ids[i]] : std::uint8_t{0};
  }
  return out;
}

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

// A bad file is an error about the flag's value: "--scene FILE: what is wrong".
Scene load_scene(const Arguments& a) {
  try {
    return load_gltf_scene(a.scene, GltfLoadOptions{a.scene_index});
  } catch (const Error& e) {
    throw Error(std::string("--scene ") + e.what());
  }
}

// `stage` always says what the run is doing, for the message if it fails.
int render(const Arguments& a, std::ostream& out, std::string& stage) {
  stage = "building the scene";
  const Scene scene = a.scene.empty() ? make_demo_scene() : load_scene(a);
  if (a.list_cameras) {
    for (const Camera& c : scene.cameras) out << c.name << ": " << c.description << '\n';
    return 0;
  }
  RendererOptions options;
  options.width = a.width;
  options.height = a.height;
  options.msaa = parse_msaa(a.msaa);
  options.tile_size = a.tile_size;
  options.path = a.path == "gpu" ? IndexPath::gpu : IndexPath::cpu;
  options.light_pass = a.light_pass == "compute" ? LightPass::compute : LightPass::raster;
  options.raw_permutations = a.permutations == "raw";
  options.coalesce = !a.no_coalesce;
  if (a.primitive != "auto") options.primitive = parse_tile_primitive(a.primitive);
  options.camera = a.camera;
  options.baselines = parse_baselines(a.baseline);
  options.timeout = Seconds(a.timeout_s);
  stage = "choosing the camera";
  (void)scene.camera(a.camera);  // an unknown camera fails before any Vulkan work

  stage = "creating the Vulkan context";
  ContextOptions context_options;
  context_options.device = a.device;
  context_options.validation = a.validation;
  const Context context(context_options);
  if (a.list_devices) {
    for (std::size_t i = 0; i < context.available_devices().size(); ++i) {
      out << i << ": " << context.available_devices()[i].name << '\n';
    }
    return 0;
  }
  stage = "preparing the output folder " + a.out;
  OutputFiles files(a.out);  // proves --out writable before the long part
  // Errors about a value name the flag that set it.
  try {
    (void)context.choose_msaa(options.msaa);
  } catch (const Error& e) {
    throw Error("--msaa " + a.msaa + ": " + e.what());
  }
  stage = fmt::format("creating the renderer ({}x{})", a.width, a.height);
  std::optional<TileRenderer> renderer_storage;
  try {
    renderer_storage.emplace(context, scene, options);
  } catch (const Error& e) {
    const std::string what = e.what();
    if (what.rfind("width ", 0) == 0 || what.rfind("height ", 0) == 0 || what.rfind("primitive ", 0) == 0) {
      throw Error("--" + what);
    }
    throw;
  }
  TileRenderer& renderer = *renderer_storage;

  // One untimed warm-up frame first: drivers (lavapipe included) compile pipelines lazily at
  // first use, which would otherwise land in the first frame's light-pass timings.
  stage = "the warm-up frame";
  renderer.render_frame();
  std::vector<FrameTimings> timings;
  FrameResult last;
  for (std::uint32_t f = 0; f < a.frames; ++f) {
    stage = fmt::format("frame {} of {}", f + 1, a.frames);
    last = renderer.render_frame();
    timings.push_back(last.timings);
  }
  const double rss_after_frames = current_rss_mib();
  stage = "reading back the frames";
  const RgbaImage classified = renderer.read_classified();
  const std::optional<RgbaImage> naive =
      options.baselines != Baselines::dynamic ? std::optional(renderer.read_naive()) : std::nullopt;
  const std::optional<RgbaImage> dynamic =
      options.baselines != Baselines::naive ? std::optional(renderer.read_dynamic()) : std::nullopt;
  const std::vector<std::uint8_t> raw_ids = renderer.raw_tile_ids();
  if (a.validation) context.require_no_validation_messages("tilelight");

  stage = "comparing the frames and writing the results to " + a.out;
  FrameReport report;
  const char* threads = std::getenv("LP_NUM_THREADS");
  report.run = {context.device_name(),
                a.width,
                a.height,
                renderer.msaa_samples(),
                a.tile_size,
                a.frames,
                a.path,
                a.permutations,
                a.camera,
                options.coalesce,
                threads != nullptr ? threads : "",
                options.light_pass == LightPass::compute ? std::string("workgroups")
                                                         : std::string(to_string(renderer.tile_primitive())),
                a.baseline,
                a.light_pass};
  report.run.scene = scene.source;
  report.run.scene_triangles = scene.triangle_count();
  count_tiles(report, raw_ids);
  report.primitives_uncoalesced = last.stats.primitives_uncoalesced;
  report.primitives_coalesced = last.stats.primitives_coalesced;
  report.rectangles = last.stats.rectangles;
  report.timings = median_timings(timings);
  report.frame_timings = timings;
  report.equivalence = compare_with_baselines(classified, naive, dynamic);

  const RgbaImage shown = display_encoded(classified);
  files.stage("frame_classified.png", encode_png(shown));
  for (const auto& [name, frame] : {std::pair{"frame_naive.png", &naive}, std::pair{"frame_dynamic.png", &dynamic}}) {
    if (*frame) {
      files.stage(name, encode_png(display_encoded(**frame)));
    } else {
      files.retire(name);
    }
  }
  {
    const Rgba8Canvas canvas = compose_tile_class_image(shown, a.tile_size, optimised_ids(raw_ids));
    files.stage("tile_classes.png", encode_png(canvas.width, canvas.height, canvas.pixels));
  }
  // Measured last, so the figure covers every frame, the read-back and the PNG encoding.
  report.process.peak_rss_mib = peak_rss_mib();
  report.process.rss_after_frames_mib = rss_after_frames;
  files.stage_text("report.json", report_json(report));
  files.commit();

  out << timing_table(report);
  out << "wrote " << (files.folder() / "frame_classified.png").string() << (naive ? ", frame_naive.png" : "")
      << (dynamic ? ", frame_dynamic.png" : "") << ", tile_classes.png, report.json\n";
  return 0;
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
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // cli.exit() prints the message (or the help); --help and --version are successes.
    const int code = cli.exit(e, out, err);
    return code == 0 ? 0 : kExitUsage;
  }
  std::string stage = "starting";
  try {
    return render(arguments, out, stage);
  } catch (...) {
    err << "tilelight: error: " << failure_message(stage, std::current_exception()) << '\n';
    return kExitError;
  }
}

}  // namespace tilelight::app
