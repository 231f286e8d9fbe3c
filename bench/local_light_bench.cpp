// tilelight_local_light_bench: the procedural scene's local lights drawn as light volumes and
// as full-screen passes (the Tabula Rasa chapter's §19.7.1 against its baseline) at several
// light counts, in one process. Every renderer of the run is alive at once and the timed frames
// go round-robin, one frame of each configuration per round, so a change of load on a shared
// machine hits them all alike. Each volume image is compared with the full-screen image of the
// same light count: the table's "pixels differ" must be 0. docs/results.md, section n.

#include "local_lights/local_light_bench_plan.h"
#include "plot/bar_chart.h"
#include "tilelight/app/camera_choice.h"
#include "tilelight/app/output_files.h"
#include "tilelight/app/report.h"
#include "tilelight/app/usage_error.h"
#include "tilelight/picture/png.h"
#include "tilelight/scene/local_light_placement.h"
#include "tilelight/scene/scene.h"
#include "tilelight/vulkan/context.h"

#include <fmt/format.h>
#include <median/median.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <map>
#include <memory>

namespace tilelight::local_light_bench {
namespace {

struct Run {
  BenchConfiguration configuration;
  std::unique_ptr<TileRenderer> renderer;
  std::vector<FrameTimings> timings;
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double median_of(const std::vector<FrameTimings>& frames, double FrameTimings::*field) {
  std::vector<double> values;
  values.reserve(frames.size());
  for (const FrameTimings& f : frames) values.push_back(f.*field);
  return median::of(std::move(values));
}

std::string configuration_name(const BenchConfiguration& c) {
  return fmt::format("{} lights, shadows {}, {}", c.lights, to_string(c.shadows),
                     to_string(c.renderer.local_light_pass));
}

// The procedural scene with `lights` lamps, one per light count, kept for the run.
Scene& scene_with(std::map<std::uint32_t, Scene>& scenes, std::uint32_t lights) {
  auto [it, inserted] = scenes.try_emplace(lights);
  if (inserted) {
    it->second = make_demo_scene();
    add_demo_lights(it->second, lights);
  }
  return it->second;
}

// Every renderer made and warmed up, then `frames` rounds of one frame each.
std::vector<Run> measure(const Context& context, std::map<std::uint32_t, Scene>& scenes,
                         const std::vector<BenchConfiguration>& configurations, std::uint32_t frames) {
  std::vector<Run> runs;
  for (const BenchConfiguration& c : configurations) {
    const auto start = std::chrono::steady_clock::now();
    std::cerr << fmt::format("[{}/{}] {}: set-up and warm-up frame", runs.size() + 1, configurations.size(),
                             configuration_name(c))
              << std::flush;
    Run run{c, std::make_unique<TileRenderer>(context, scene_with(scenes, c.lights), c.renderer), {}};
    (void)run.renderer->render_frame();  // takes the drivers' lazy pipeline compilation out of the timings
    runs.push_back(std::move(run));
    std::cerr << fmt::format(" ({:.1f} s)\n", seconds_since(start));
  }
  for (std::uint32_t f = 0; f < frames; ++f) {
    const auto start = std::chrono::steady_clock::now();
    std::cerr << fmt::format("round {}/{}", f + 1, frames) << std::flush;
    for (Run& run : runs) run.timings.push_back(run.renderer->render_frame().timings);
    std::cerr << fmt::format(" ({:.1f} s)\n", seconds_since(start));
  }
  return runs;
}

// Medians, and each image against the first pass's image of the same light count and shadows.
std::vector<BenchRow> rows_of(const std::vector<Run>& runs) {
  std::vector<BenchRow> rows;
  std::map<std::pair<std::uint32_t, ShadowMode>, RgbaImage> reference;  // the first pass's image
  for (const Run& run : runs) {
    BenchRow row{run.configuration, median_of(run.timings, &FrameTimings::local_lights),
                 median_of(run.timings, &FrameTimings::local_light_shadows),
                 median_of(run.timings, &FrameTimings::frame_classified), run.renderer->local_light_shadow_pool()};
    RgbaImage image = run.renderer->read_classified();
    const auto [it, first] =
        reference.try_emplace({run.configuration.lights, run.configuration.shadows}, std::move(image));
    if (!first) {
      const app::Equivalence e = app::compare_frames(image, it->second);
      row.pixels_different = e.pixels_different;
      row.max_abs_difference = e.max_abs_difference;
    }
    rows.push_back(row);
  }
  return rows;
}

std::string results_json(const BenchOptions& options, const std::string& device, const std::vector<BenchRow>& rows,
                         const std::vector<Run>& runs) {
  nlohmann::json j;
  j["device"] = device;
  j["size"] = {options.width, options.height};
  j["camera"] = options.camera;
  j["msaa_samples"] = runs.front().renderer->msaa_samples();
  j["light_pass"] = to_string(options.light_pass);
  j["frames"] = options.frames;
  j["configurations"] = nlohmann::json::array();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    nlohmann::json frames = nlohmann::json::array();
    for (const FrameTimings& f : runs[i].timings) {
      frames.push_back({{"local_lights", f.local_lights},
                        {"local_light_shadows", f.local_light_shadows},
                        {"frame_classified", f.frame_classified}});
    }
    const BenchRow& r = rows[i];
    j["configurations"].push_back(
        {{"lights", r.configuration.lights},
         {"shadows", to_string(r.configuration.shadows)},
         {"local_light_pass", to_string(r.configuration.renderer.local_light_pass)},
         {"shadow_maps",
          {{"maps", r.pool.maps}, {"faces", r.pool.faces}, {"bytes", r.pool.bytes}, {"unshadowed", r.pool.unshadowed}}},
         {"median_ms",
          {{"local_lights", r.local_lights_ms}, {"local_light_shadows", r.shadow_maps_ms}, {"frame", r.frame_ms}}},
         {"frames_ms", frames},
         {"pixels_different", r.pixels_different},
         {"max_abs_difference", r.max_abs_difference}});
  }
  return j.dump(2) + "\n";
}

plot::BarChart chart_of(const BenchOptions& options, const std::vector<BenchRow>& rows) {
  plot::BarChart chart;
  chart.title = fmt::format("Local lights: volumes vs full-screen ({}x{}, {} camera)", options.width, options.height,
                            options.camera);
  chart.category_axis = "lights, shadows";
  chart.value_axis = "median time of the local-light pass (ms)";
  for (const LocalLightPass pass : options.passes) chart.series.push_back(to_string(pass));
  for (const std::uint32_t lights : options.lights) {
    for (const ShadowMode shadows : options.shadows) {
      chart.categories.push_back(fmt::format("{}, shadows {}", lights, to_string(shadows)));
      std::vector<double> values;
      for (const LocalLightPass pass : options.passes) {
        for (const BenchRow& r : rows) {
          const BenchConfiguration& c = r.configuration;
          if (c.lights == lights && c.shadows == shadows && c.renderer.local_light_pass == pass) {
            values.push_back(r.local_lights_ms);
          }
        }
      }
      chart.values.push_back(std::move(values));
    }
  }
  chart.decimals = 1;
  return chart;
}

int run_bench(const BenchOptions& options) {
  std::map<std::uint32_t, Scene> scenes;
  {  // an unknown camera is a usage error before any Vulkan work
    app::CameraRequest request;
    request.camera = options.camera;
    (void)app::choose_camera(request, scene_with(scenes, options.lights.front()),
                             static_cast<float>(options.width) / static_cast<float>(options.height));
  }
  ContextOptions context_options;
  context_options.device = options.device;
  const Context context(context_options);
  app::OutputFiles files(options.out);  // proves --out writable before the long part
  const std::vector<Run> runs = measure(context, scenes, bench_configurations(options), options.frames);
  const std::vector<BenchRow> rows = rows_of(runs);
  const char* threads = std::getenv("LP_NUM_THREADS");
  std::cout << fmt::format(
                   "Device: {}, {}x{}, {}x MSAA, {} camera, {} global light pass, median of {} frame(s) after 1 "
                   "warm-up frame (round-robin), LP_NUM_THREADS={}\n\n",
                   context.device_name(), options.width, options.height, runs.front().renderer->msaa_samples(),
                   options.camera, to_string(options.light_pass), options.frames,
                   threads != nullptr ? threads : "(default)")
            << markdown_table(options, rows);
  const Rgba8Canvas chart = plot::draw_bar_chart(chart_of(options, rows));
  files.stage("local_lights.png", encode_png(chart.width, chart.height, chart.pixels));
  files.stage_text("results.json", results_json(options, context.device_name(), rows, runs));
  files.commit();
  std::cerr << "wrote " << (files.folder() / "results.json").string() << " and local_lights.png\n";
  for (const BenchRow& r : rows) {
    if (r.pixels_different != 0) {
      std::cerr << fmt::format("tilelight_local_light_bench: error: {}: {} pixels differ from the {} image\n",
                               configuration_name(r.configuration), r.pixels_different,
                               to_string(options.passes.front()));
      return 1;
    }
  }
  return 0;
}

}  // namespace
}  // namespace tilelight::local_light_bench

int main(int argc, char** argv) {
  using namespace tilelight::local_light_bench;
  BenchOptions options;
  int exit_code = 0;
  try {
    if (!parse_bench_options(argc, argv, options, exit_code, std::cout, std::cerr)) return exit_code;
    return run_bench(options);
  } catch (const tilelight::app::UsageError& e) {
    std::cerr << e.what() << "\nRun with --help for more information.\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "tilelight_local_light_bench: error: " << e.what() << '\n';
    return 1;
  }
}
