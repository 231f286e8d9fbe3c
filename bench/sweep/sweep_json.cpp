#include "sweep_json.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace tilelight::sweep {
namespace {

using Json = nlohmann::ordered_json;

double round3(double value) { return std::round(value * 1000.0) / 1000.0; }

Json timings_json(const app::MedianTimings& t) {
  Json j;
  j["shadow_map"] = round3(t.shadow_map);
  j["gbuffer"] = round3(t.gbuffer);
  j["classification"] = round3(t.classification);
  j["index_build_cpu"] = round3(t.index_build_cpu);
  j["index_build_gpu"] = round3(t.index_build_gpu);
  j["tiled_light"] = round3(t.tiled_light);
  j["naive_light"] = round3(t.naive_light);
  j["dynamic_light"] = round3(t.dynamic_light);
  return j;
}

Json measurement_json(const Measurement& m) {
  const RendererOptions& o = m.options;
  Json j;
  j["key"] = m.key;
  j["width"] = o.width;
  j["height"] = o.height;
  j["msaa_samples"] = m.msaa_samples;
  j["camera"] = o.camera;
  j["sky_tiles"] = m.sky_tiles;
  j["tile_size"] = o.tile_size;
  j["path"] = o.path == IndexPath::gpu ? "gpu" : "cpu";
  j["permutations"] = o.raw_permutations ? "raw" : "optimised";
  j["coalesce"] = o.coalesce;
  j["pipelines"] = m.pipelines;
  j["tiles"] = m.tiles;
  j["primitive"] = to_string(m.primitive);
  j["primitives"] = {
      {"uncoalesced", m.primitives_uncoalesced}, {"drawn", m.primitives_coalesced}, {"rectangles", m.rectangles}};
  j["timings_ms"] = timings_json(m.timings);
  j["classified_light_ms"] = round3(m.classified_light());
  j["speedup"] = std::round(m.speedup() * 100.0) / 100.0;
  j["speedup_over_dynamic"] = std::round(m.speedup_over_dynamic() * 100.0) / 100.0;
  j["equivalence"] = {{"pixels_different", m.equivalence.pixels_different},
                      {"max_abs_difference", m.equivalence.max_abs_difference}};
  j["dynamic_equivalence"] = {{"pixels_different", m.dynamic_equivalence.pixels_different},
                              {"max_abs_difference", m.dynamic_equivalence.max_abs_difference}};
  return j;
}

}  // namespace

std::string results_json(const SweepRun& run) {
  Json j;
  j["device"] = run.device;
  j["frames"] = run.options->frames;
  j["warmup_frames"] = 1;
  j["schedule"] = "round-robin";  // timed frame f of every configuration before frame f + 1 of any
  j["camera"] = run.plan->configurations.front().camera;
  j["scene"] = run.scene.empty() ? Json(nullptr) : Json(run.scene);
  j["scene_triangles"] = run.scene_triangles;
  Json sizes = Json::array();
  for (const FrameSize& s : run.options->sizes) sizes.push_back(s.name);
  j["sizes"] = sizes;
  j["lavapipe_threads"] = run.lavapipe_threads.empty() ? Json(nullptr) : Json(run.lavapipe_threads);
  Json configurations = Json::array();
  for (const Measurement& m : *run.measurements) configurations.push_back(measurement_json(m));
  j["configurations"] = configurations;
  Json comparisons = Json::array();
  for (const Comparison& c : run.plan->comparisons) {
    comparisons.push_back({{"id", c.id}, {"title", c.title}, {"image", c.id + ".png"}, {"configurations", c.keys}});
  }
  j["comparisons"] = comparisons;
  return j.dump(2) + "\n";
}

}  // namespace tilelight::sweep
