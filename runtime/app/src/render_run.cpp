#include "render_run.h"

#include "tilelight/app/camera_choice.h"

#include "tilelight/app/frame_ratios.h"
#include "tilelight/app/output_files.h"
#include "tilelight/app/process_stats.h"
#include "tilelight/app/report.h"
#include "tilelight/app/usage_error.h"
#include "tilelight/gltf/load_gltf.h"
#include "tilelight/picture/png.h"
#include "tilelight/picture/tile_class_image.h"
#include "tilelight/render/tile_renderer.h"
#include "tilelight/scene/local_light_counts.h"
#include "tilelight/scene/local_light_placement.h"
#include "tilelight/scene/scene.h"
#include "tilelight/vulkan/context.h"
#include "tilelight/vulkan/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <optional>
#include <vector>

namespace tilelight::app {
namespace {

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

// --lights places lights in the procedural scene; a --scene file has its own (or none).
void refuse_lights_with_scene(const Arguments& a) {
  if (!a.lights || a.scene.empty()) return;
  throw UsageError("--lights",
                   fmt::format("--lights {}: the procedural scene's lights, not --scene {}'s; the file's own "
                               "lights (KHR_lights_punctual) are used",
                               *a.lights, a.scene));
}

// The procedural scene with the --lights it asks for.
GltfScene procedural_scene(const Arguments& a) {
  GltfScene procedural{make_demo_scene(), {}};
  add_demo_lights(procedural.scene, a.lights.value_or(0));
  return procedural;
}

// The procedural scene, or the --scene file with its warnings. A bad file is an error about
// the flag's value: "--scene FILE: what is wrong".
GltfScene load_scene(const Arguments& a) {
  refuse_lights_with_scene(a);
  if (a.scene.empty()) return procedural_scene(a);
  try {
    return load_gltf(a.scene, GltfLoadOptions{a.scene_index});
  } catch (const Error& e) {
    throw OptionError("--scene", std::string("--scene ") + e.what());
  }
}

RendererOptions renderer_options(const Arguments& a, const ChosenCamera& camera) {
  RendererOptions options;
  options.width = a.width;
  options.height = a.height;
  options.msaa = a.msaa;
  options.tile_size = a.tile_size;
  options.path = a.path;
  options.light_pass = a.light_pass;
  options.light_kinds = a.light_kinds;
  options.local_light_pass = a.local_light_pass;
  options.local_light_shadows = a.local_light_shadows;
  options.local_light_shadow_cache = a.local_light_shadow_cache;
  options.raw_permutations = a.raw_permutations;
  options.coalesce = !a.no_coalesce;
  options.cull_batches = !a.no_cull;
  if (a.primitive != "auto") options.primitive = parse_tile_primitive(a.primitive);
  options.camera = camera.name;
  options.camera_pose = camera.placed;
  options.baselines = a.baseline;
  options.timeout = Seconds(a.timeout_s);
  return options;
}

// Errors about a value name the flag that set it.
std::unique_ptr<TileRenderer> make_renderer(const Context& context, const Scene& scene,
                                            const RendererOptions& options) {
  try {
    return std::make_unique<TileRenderer>(context, scene, options);
  } catch (const OptionError& e) {
    // The renderer's options are the flags of the same names.
    throw OptionError("--" + e.option(), "--" + std::string(e.what()));
  }
}

struct TimedFrames {
  std::vector<FrameTimings> timings;
  FrameResult last;
  double rss_after_frames_mib = 0;
};

TimedFrames render_frames(TileRenderer& renderer, std::uint32_t frames, std::string& stage) {
  // One untimed warm-up frame first: drivers (lavapipe included) compile pipelines lazily at
  // first use, which would otherwise land in the first frame's light-pass timings.
  stage = "the warm-up frame";
  renderer.render_frame();
  TimedFrames timed;
  for (std::uint32_t f = 0; f < frames; ++f) {
    stage = fmt::format("frame {} of {}", f + 1, frames);
    timed.last = renderer.render_frame();
    timed.timings.push_back(timed.last.timings);
  }
  timed.rss_after_frames_mib = current_rss_mib();
  return timed;
}

struct ReadBack {
  RgbaImage classified;
  std::optional<RgbaImage> naive, dynamic, floor;  // the baselines that ran
  std::vector<std::uint8_t> raw_ids;
};

ReadBack read_back(const TileRenderer& renderer, Baselines baselines) {
  ReadBack frames;
  frames.classified = renderer.read_classified();
  if (runs_naive(baselines)) frames.naive = renderer.read_naive();
  if (runs_dynamic(baselines)) frames.dynamic = renderer.read_dynamic();
  if (runs_floor(baselines)) frames.floor = renderer.read_floor();
  frames.raw_ids = renderer.raw_tile_ids();
  return frames;
}

FrameReport make_report(const Arguments& a, const ChosenCamera& camera, const Context& context, const Scene& scene,
                        const TileRenderer& renderer, const TimedFrames& timed, const ReadBack& frames) {
  FrameReport report;
  const char* threads = std::getenv("LP_NUM_THREADS");
  report.run = {context.device_name(),
                a.width,
                a.height,
                renderer.msaa_samples(),
                a.tile_size,
                a.frames,
                a.path,
                a.raw_permutations,
                camera.name,
                !a.no_coalesce,
                threads != nullptr ? threads : "",
                renderer.light_pass() == LightPass::compute ? std::string("workgroups")
                                                            : std::string(to_string(renderer.tile_primitive())),
                a.baseline,
                a.light_pass};
  report.run.local_light_pass = a.local_light_pass;
  report.run.light_kinds = renderer.light_kinds();
  report.run.tile_pipelines = renderer.pipeline_count();
  report.run.tile_pipelines_ms = renderer.tile_pipelines_ms();
  report.run.forward_instances = renderer.forward_instances();
  report.run.scene = scene.source;
  report.run.scene_triangles = scene.triangle_count();
  report.run.local_lights = count_local_lights(scene.local_lights);
  report.run.camera_pose = camera.pose;
  count_tiles(report, frames.raw_ids);
  report.primitives_uncoalesced = timed.last.stats.primitives_uncoalesced;
  report.primitives_coalesced = timed.last.stats.primitives_coalesced;
  report.rectangles = timed.last.stats.rectangles;
  report.timings = median_timings(timed.timings);
  report.frame_timings = timed.timings;
  report.ratios = frame_ratios(timed.timings);
  if (frames.naive || frames.dynamic) {
    report.equivalence = compare_with_baselines(frames.classified, frames.naive, frames.dynamic);
  }
  report.process.rss_after_frames_mib = timed.rss_after_frames_mib;
  return report;
}

// Stages the pictures and report.json and commits them together.
void write_outputs(OutputFiles& files, FrameReport& report, const ReadBack& frames, std::uint32_t tile_size) {
  const RgbaImage shown = display_encoded(frames.classified);
  files.stage("frame_classified.png", encode_png(shown));
  for (const auto& [name, frame] :
       {std::pair{"frame_naive.png", &frames.naive}, std::pair{"frame_dynamic.png", &frames.dynamic},
        std::pair{"frame_floor.png", &frames.floor}}) {
    if (*frame) {
      files.stage(name, encode_png(display_encoded(**frame)));
    } else {
      files.retire(name);
    }
  }
  const Rgba8Canvas canvas = compose_tile_class_image(shown, tile_size, optimised_tile_ids(frames.raw_ids));
  files.stage("tile_classes.png", encode_png(canvas.width, canvas.height, canvas.pixels));
  // Measured last, so the figure covers every frame, the read-back and the PNG encoding.
  report.process.peak_rss_mib = peak_rss_mib();
  files.stage_text("report.json", report_json(report));
  files.commit();
}

}  // namespace

int render_run(const Arguments& a, std::ostream& out, std::ostream& err, std::string& stage) {
  stage = "building the scene";
  const auto load_start = std::chrono::steady_clock::now();
  GltfScene loaded = load_scene(a);
  const double parse_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - load_start).count();
  for (const std::string& warning : loaded.warnings) err << warning << '\n';
  Scene& scene = loaded.scene;  // the camera's fit adjusts its sun (choose_camera())
  if (a.list_cameras) {
    for (const Camera& c : scene.cameras) out << c.name << ": " << c.description << '\n';
    return 0;
  }
  stage = "choosing the camera";
  // An unknown camera fails before any Vulkan work.
  CameraRequest request = a.view;
  request.scene_file = a.scene;
  const ChosenCamera camera = choose_camera(request, scene, static_cast<float>(a.width) / static_cast<float>(a.height));
  const RendererOptions options = renderer_options(a, camera);

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
  stage = fmt::format("creating the renderer ({}x{})", a.width, a.height);
  const std::unique_ptr<TileRenderer> renderer = make_renderer(context, scene, options);
  const LocalLightShadowPool shadow_pool = renderer->local_light_shadow_pool();
  if (shadow_pool.unshadowed != 0) {
    err << fmt::format(
        "warning: {} local light(s) cast shadows but are drawn unshadowed: the shadow-map pool's cap of {} MiB "
        "holds {} faces of {}x{} (report.json local_light_shadows)\n",
        shadow_pool.unshadowed, shadow_pool.cap_bytes >> 20, shadow_pool.faces, shadow_pool.face_size,
        shadow_pool.face_size);
  }

  const TimedFrames timed = render_frames(*renderer, a.frames, stage);
  stage = "reading back the frames";
  const ReadBack frames = read_back(*renderer, options.baselines);
  if (a.validation) context.require_no_validation_messages("tilelight");

  stage = "comparing the frames and writing the results to " + a.out;
  FrameReport report = make_report(a, camera, context, scene, *renderer, timed, frames);
  report.run.scene_warnings = loaded.warnings;
  report.run.cull = options.cull_batches;
  report.load_ms = parse_ms + renderer->scene_upload_ms();
  report.culled = renderer->culled_batches();
  report.local_light_shadows = shadow_pool;
  write_outputs(files, report, frames, a.tile_size);

  out << timing_table(report);
  out << "wrote " << (files.folder() / "frame_classified.png").string() << (frames.naive ? ", frame_naive.png" : "")
      << (frames.dynamic ? ", frame_dynamic.png" : "") << (frames.floor ? ", frame_floor.png" : "")
      << ", tile_classes.png, report.json\n";
  return 0;
}

}  // namespace tilelight::app
