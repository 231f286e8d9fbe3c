#include "measurement.h"

#include <fmt/format.h>
#include <median/median.h>

#include <split_second_shaders.h>

#include <algorithm>
#include <chrono>
#include <memory>

namespace tilelight::sweep {
namespace {

struct Run {
  std::unique_ptr<TileRenderer> renderer;
  std::vector<FrameTimings> timings;
  FrameResult last;
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Measurement finish(const Run& run, const RendererOptions& options, std::uint32_t frames) {
  Measurement m;
  m.key = configuration_key(options);
  m.options = options;
  m.frames = frames;
  m.timings = all_medians(run.timings);
  m.frame_timings = run.timings;
  m.msaa_samples = run.renderer->msaa_samples();
  m.pipelines = run.renderer->pipeline_count();
  m.tile_pipelines_ms = run.renderer->tile_pipelines_ms();
  m.tiles = run.renderer->grid().tile_count();
  m.primitives_uncoalesced = run.last.stats.primitives_uncoalesced;
  m.primitives_coalesced = run.last.stats.primitives_coalesced;
  m.rectangles = run.last.stats.rectangles;
  m.primitive = run.renderer->tile_primitive();
  m.culled = run.renderer->culled_batches();
  const std::vector<std::uint8_t> ids = run.renderer->raw_tile_ids();
  m.sky_tiles = static_cast<std::uint32_t>(std::count_if(
      ids.begin(), ids.end(), [](std::uint8_t id) { return (id & split_second::raw_bit::SKY.value()) != 0; }));
  const RgbaImage naive = run.renderer->read_naive();
  m.equivalence = app::compare_frames(run.renderer->read_classified(), naive);
  m.dynamic_equivalence = app::compare_frames(run.renderer->read_dynamic(), naive);
  return m;
}

}  // namespace

double Measurement::speedup() const {
  const double classified = classified_light();
  return classified > 0 ? timings.naive_light / classified : 0.0;
}

double Measurement::speedup_over_dynamic() const {
  const double classified = classified_light();
  return classified > 0 ? timings.dynamic_light / classified : 0.0;
}

app::MedianTimings all_medians(const std::vector<FrameTimings>& frames) {
  app::MedianTimings m = app::median_timings(frames);
  for (double FrameTimings::*field :
       {&FrameTimings::gbuffer_plain, &FrameTimings::floor_light, &FrameTimings::frame_classified,
        &FrameTimings::frame_naive, &FrameTimings::frame_dynamic}) {
    std::vector<double> values;
    values.reserve(frames.size());
    for (const FrameTimings& f : frames) values.push_back(f.*field);
    m.*field = median::of(values);
  }
  return m;
}

std::string configuration_key(const RendererOptions& o) {
  std::string key =
      fmt::format("{}x{} tile {} {} {} {} {} camera {} msaa {} {}", o.width, o.height, o.tile_size,
                  o.path == IndexPath::gpu ? "gpu" : "cpu", o.raw_permutations ? "raw" : "optimised",
                  o.coalesce ? "coalesced" : "uncoalesced", o.primitive ? to_string(*o.primitive) : "auto", o.camera,
                  o.msaa == 0 ? std::string("auto") : std::to_string(o.msaa), to_string(o.light_pass));
  if (o.baselines != Baselines::both) key += fmt::format(" baselines {}", to_string(o.baselines));
  if (!o.cull_batches) key += " no-cull";
  if (o.light_kinds != LightKinds::variant) key += fmt::format(" kinds {}", to_string(o.light_kinds));
  return key;
}

std::vector<Measurement> measure_round_robin(const Context& context, const SceneFor& scene_for,
                                             std::vector<RendererOptions> configurations, std::uint32_t frames,
                                             std::ostream& progress) {
  const std::size_t n = configurations.size();
  std::vector<Run> runs(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto start = std::chrono::steady_clock::now();
    progress << fmt::format("[{}/{}] {}: set-up and warm-up frame", i + 1, n, configuration_key(configurations[i]))
             << std::flush;
    const Scene& scene = scene_for(configurations[i]);
    runs[i].renderer = std::make_unique<TileRenderer>(context, scene, configurations[i]);
    // The warm-up frame takes the drivers' lazy pipeline compilation out of the timings.
    runs[i].renderer->render_frame();
    progress << fmt::format(" ({:.1f} s)\n", seconds_since(start));
  }
  for (std::uint32_t f = 0; f < frames; ++f) {
    const auto start = std::chrono::steady_clock::now();
    progress << fmt::format("round {}/{}: one frame of each configuration", f + 1, frames) << std::flush;
    for (Run& run : runs) {
      run.last = run.renderer->render_frame();
      run.timings.push_back(run.last.timings);
    }
    progress << fmt::format(" ({:.1f} s)\n", seconds_since(start));
  }
  std::vector<Measurement> measurements;
  for (std::size_t i = 0; i < n; ++i) {
    measurements.push_back(finish(runs[i], configurations[i], frames));
    const Measurement& m = measurements.back();
    progress << fmt::format("[{}/{}] {}: speed-up {:.2f}x over naive, {:.2f}x over dynamic; {} pixels differ\n", i + 1,
                            n, m.key, m.speedup(), m.speedup_over_dynamic(), m.equivalence.pixels_different);
    runs[i].renderer.reset();  // its memory is not needed any more
  }
  return measurements;
}

}  // namespace tilelight::sweep
