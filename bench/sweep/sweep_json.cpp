#include "sweep_json.h"

#include "gbuffer_bound.h"

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
  j["gbuffer_plain"] = round3(t.gbuffer_plain);
  j["floor_light"] = round3(t.floor_light);
  j["frame_classified"] = round3(t.frame_classified);
  j["frame_naive"] = round3(t.frame_naive);
  j["frame_dynamic"] = round3(t.frame_dynamic);
  return j;
}

double round2(double value) { return std::round(value * 100.0) / 100.0; }

Json ratio_json(const std::optional<app::RatioStats>& r) {
  if (!r) return nullptr;
  return {{"median", round2(r->median)}, {"min", round2(r->min)}, {"max", round2(r->max)}};
}

// Baseline over classified, frame by frame (frame_ratios.h); null where the baseline did not run.
Json ratios_json(const app::FrameRatios& r) {
  return {{"light_vs_naive", ratio_json(r.light_vs_naive)},
          {"light_vs_dynamic", ratio_json(r.light_vs_dynamic)},
          {"whole_frame_vs_naive", ratio_json(r.whole_frame_vs_naive)},
          {"whole_frame_vs_dynamic", ratio_json(r.whole_frame_vs_dynamic)}};
}

Json measurement_json(const Measurement& m, std::optional<double> bandwidth) {
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
  j["light_kinds"] = to_string(o.light_kinds);
  j["tile_pipelines_ms"] = round3(m.tile_pipelines_ms);
  if (m.spec_build) {
    j["spec_build"] = {{"spec", m.spec_build->spec},
                       {"sources", m.spec_build->sources},
                       {"spirv_blobs", m.spec_build->blobs},
                       {"seconds", round3(m.spec_build->seconds)}};
  }
  j["tiles"] = m.tiles;
  j["primitive"] = to_string(m.primitive);
  j["primitives"] = {
      {"uncoalesced", m.primitives_uncoalesced}, {"drawn", m.primitives_coalesced}, {"rectangles", m.rectangles}};
  j["baselines"] = to_string(o.baselines);
  j["cull"] = o.cull_batches;
  j["culled"] = {{"gbuffer_batches", m.culled.gbuffer}, {"shadow_batches", m.culled.shadow}};
  j["timings_ms"] = timings_json(m.timings);
  Json frames = Json::array();
  for (const FrameTimings& f : m.frame_timings) frames.push_back(timings_json(f));
  j["frame_timings_ms"] = frames;
  j["classified_light_ms"] = round3(m.classified_light());
  j["speedup"] = round2(m.speedup());
  j["speedup_over_dynamic"] = round2(m.speedup_over_dynamic());
  j["frame_ratios"] = ratios_json(m.ratios());
  const std::uint64_t bytes = gbuffer_bytes(o.width, o.height, m.msaa_samples);
  j["gbuffer_bytes"] = bytes;
  const std::optional<double> bound = gbuffer_read_bound_ms(bytes, bandwidth);
  j["gbuffer_read_bound_ms"] = bound ? Json(std::round(*bound * 1e4) / 1e4) : Json(nullptr);
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
  const std::optional<double> bandwidth = memory_bandwidth(run.device);
  j["memory_bandwidth_bytes_per_s"] = bandwidth ? Json(*bandwidth) : Json(nullptr);
  j["frames"] = run.options->frames;
  j["warmup_frames"] = 1;
  j["schedule"] = "round-robin";  // timed frame f of every configuration before frame f + 1 of any
  j["camera"] = run.plan->configurations.front().camera;
  j["scene"] = run.scene.empty() ? Json(nullptr) : Json(run.scene);
  j["scene_triangles"] = run.scene_triangles;
  j["scene_warnings"] = run.scene_warnings;
  Json sizes = Json::array();
  for (const FrameSize& s : run.options->sizes) sizes.push_back(s.name);
  j["sizes"] = sizes;
  j["lavapipe_threads"] = run.lavapipe_threads.empty() ? Json(nullptr) : Json(run.lavapipe_threads);
  Json configurations = Json::array();
  for (const Measurement& m : *run.measurements) configurations.push_back(measurement_json(m, bandwidth));
  j["configurations"] = configurations;
  Json comparisons = Json::array();
  for (const Comparison& c : run.plan->comparisons) {
    comparisons.push_back({{"id", c.id}, {"title", c.title}, {"image", c.id + ".png"}, {"configurations", c.keys}});
  }
  j["comparisons"] = comparisons;
  return j.dump(2) + "\n";
}

}  // namespace tilelight::sweep
