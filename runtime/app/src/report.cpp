#include "tilelight/app/report.h"

#include "tilelight/base/error.h"

#include <median/median.h>
#include <split_second_shaders.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <utility>

namespace tilelight::app {
namespace {

double round3(double value) { return std::round(value * 1000.0) / 1000.0; }

// Every timed stage, by its report.json name, in the report's order.
constexpr std::array<std::pair<const char*, double FrameTimings::*>, 8> kStages{{
    {"gbuffer", &FrameTimings::gbuffer},
    {"shadow_map", &FrameTimings::shadow_map},
    {"classification", &FrameTimings::classification},
    {"index_build_cpu", &FrameTimings::index_build_cpu},
    {"index_build_gpu", &FrameTimings::index_build_gpu},
    {"tiled_light", &FrameTimings::tiled_light},
    {"naive_light", &FrameTimings::naive_light},
    {"dynamic_light", &FrameTimings::dynamic_light},
}};

nlohmann::ordered_json equivalence_json(const Equivalence& e) {
  return {{"max_abs_difference", e.max_abs_difference}, {"pixels_different", e.pixels_different}};
}

}  // namespace

std::vector<std::uint8_t> optimised_tile_ids(const std::vector<std::uint8_t>& raw_ids) {
  std::vector<std::uint8_t> out(raw_ids.size());
  for (std::size_t i = 0; i < raw_ids.size(); ++i) {
    const std::optional<std::uint32_t> id = split_second::optimised_id(raw_ids[i]);
    if (!id) {
      throw Error(
          fmt::format("tile {}: raw ID {} is {}", i, raw_ids[i],
                      raw_ids[i] < split_second::kRawCount ? "impossible (a pruned class)" : "out of range (0..127)"));
    }
    out[i] = static_cast<std::uint8_t>(*id);
  }
  return out;
}

void count_tiles(FrameReport& report, const std::vector<std::uint8_t>& raw_ids) {
  namespace bit = split_second::raw_bit;
  const std::vector<std::pair<std::string, std::uint32_t>> properties{{"SKY", bit::SKY},
                                                                      {"SUN_LIGHT", bit::SUN_LIGHT},
                                                                      {"SOLID_SHADOW", bit::SHADOW_SOLID},
                                                                      {"SOFT_SHADOW", bit::SHADOW_SOFT},
                                                                      {"SHADOW_FADE", bit::SHADOW_FADE},
                                                                      {"LIGHT_SCATTERING", bit::LIGHT_SCATTERING},
                                                                      {"MSAA_EDGE", bit::MSAA_EDGE}};
  report.tiles = static_cast<std::uint32_t>(raw_ids.size());
  report.raw_property_tiles.clear();
  for (const auto& [name, mask] : properties) {
    const auto count =
        std::count_if(raw_ids.begin(), raw_ids.end(), [mask = mask](std::uint8_t id) { return (id & mask) != 0; });
    report.raw_property_tiles.emplace_back(name, static_cast<std::uint32_t>(count));
  }
  report.optimised_tiles.assign(split_second::kOptimisedCount, 0);
  for (std::uint8_t id : optimised_tile_ids(raw_ids)) ++report.optimised_tiles[id];
}

MedianTimings median_timings(const std::vector<FrameTimings>& frames) {
  MedianTimings m;
  for (const auto& [name, field] : kStages) {
    std::vector<double> values;
    values.reserve(frames.size());
    for (const FrameTimings& f : frames) values.push_back(f.*field);
    m.*field = median::of(values);
  }
  return m;
}

Equivalence compare_frames(const RgbaImage& classified, const RgbaImage& naive) {
  Equivalence e;
  const std::size_t pixels = static_cast<std::size_t>(classified.width) * classified.height;
  for (std::size_t p = 0; p < pixels; ++p) {
    bool differs = false;
    for (std::size_t c = 0; c < 4; ++c) {
      const float a = classified.pixels[p * 4 + c];
      const float b = naive.pixels[p * 4 + c];
      if (a == b || (std::isnan(a) && std::isnan(b))) continue;
      differs = true;
      const double d = std::fabs(static_cast<double>(a) - static_cast<double>(b));
      e.max_abs_difference = std::max(e.max_abs_difference, std::isnan(d) ? INFINITY : d);
    }
    if (differs) ++e.pixels_different;
  }
  return e;
}

Equivalences compare_with_baselines(const RgbaImage& classified, const std::optional<RgbaImage>& naive,
                                    const std::optional<RgbaImage>& dynamic) {
  Equivalences e;
  e.reference = naive ? "naive" : "dynamic";
  e.classified = compare_frames(classified, naive ? *naive : *dynamic);
  if (naive && dynamic) e.dynamic = compare_frames(*dynamic, *naive);
  return e;
}

std::string report_json(const FrameReport& r) {
  nlohmann::ordered_json j;
  j["device"] = r.run.device;
  j["width"] = r.run.width;
  j["height"] = r.run.height;
  j["msaa_samples"] = r.run.msaa_samples;
  j["tile_size"] = r.run.tile_size;
  j["path"] = r.run.path;
  j["permutations"] = r.run.permutations;
  j["camera"] = r.run.camera;
  // The --scene file's name, or null for the procedural scene; the triangles of either.
  j["scene"] = r.run.scene.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(r.run.scene);
  j["scene_triangles"] = r.run.scene_triangles;
  j["coalesce"] = r.run.coalesce;
  j["primitive"] = r.run.primitive;
  j["baselines"] = r.run.baselines;
  j["light_pass"] = r.run.light_pass;
  j["frames"] = r.run.frames;
  j["lavapipe_threads"] =
      r.run.lavapipe_threads.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(r.run.lavapipe_threads);
  j["tiles"] = r.tiles;
  nlohmann::ordered_json properties = nlohmann::ordered_json::object();
  for (const auto& [name, count] : r.raw_property_tiles) properties[name] = count;
  j["raw_property_tiles"] = properties;
  j["optimised_tiles"] = r.optimised_tiles;
  j["primitives"] = {
      {"uncoalesced", r.primitives_uncoalesced}, {"coalesced", r.primitives_coalesced}, {"rectangles", r.rectangles}};
  // The medians, and every frame's figures, so that a benchmark can take other statistics than
  // the median, or ratios within one frame (on a machine whose speed drifts, the steadier figure).
  nlohmann::ordered_json timings, frames;
  for (const auto& [name, field] : kStages) {
    timings[name] = round3(r.timings.*field);
    nlohmann::ordered_json values = nlohmann::ordered_json::array();
    for (const FrameTimings& f : r.frame_timings) values.push_back(round3(f.*field));
    frames[name] = values;
  }
  j["timings_ms"] = timings;
  j["frame_timings_ms"] = frames;
  // `equivalence`: the classified frame against `reference`; `dynamic_equivalence`: the dynamic
  // frame against the naive one (null unless both ran).
  j["equivalence"] = equivalence_json(r.equivalence.classified);
  j["equivalence"]["reference"] = r.equivalence.reference;
  j["dynamic_equivalence"] =
      r.equivalence.dynamic ? equivalence_json(*r.equivalence.dynamic) : nlohmann::ordered_json(nullptr);
  j["process"] = {{"peak_rss_mib", std::round(r.process.peak_rss_mib * 10.0) / 10.0},
                  {"rss_after_frames_mib", std::round(r.process.rss_after_frames_mib * 10.0) / 10.0}};
  return j.dump(2) + "\n";
}

std::string timing_table(const FrameReport& r) {
  const MedianTimings& t = r.timings;
  const bool naive = r.run.baselines != "dynamic";
  const bool dynamic = r.run.baselines != "naive";
  const double classified_light = t.classification + t.index_build_cpu + t.index_build_gpu + t.tiled_light;
  auto cell = [](bool ran, double ms) { return ran ? fmt::format("{:.3f}", ms) : std::string("-"); };
  std::string out;
  out += fmt::format("{}x{}, {}x MSAA, {}, {} light pass, path {}, {} permutations, camera {}, median of {} frame(s)\n",
                     r.run.width, r.run.height, r.run.msaa_samples, r.run.device, r.run.light_pass, r.run.path,
                     r.run.permutations, r.run.camera, r.run.frames);
  out +=
      fmt::format("scene {} ({} triangles)\n", r.run.scene.empty() ? "procedural" : r.run.scene, r.run.scene_triangles);
  out += fmt::format("{:<28}{:>12}{:>12}{:>14}\n", "stage (ms)", "naive", "dynamic", "classified");
  auto row = [&](const char* name, bool in_baselines, double naive_ms, double dynamic_ms, double classified_ms) {
    out += fmt::format("{:<28}{:>12}{:>12}{:>14.3f}\n", name, cell(naive && in_baselines, naive_ms),
                       cell(dynamic && in_baselines, dynamic_ms), classified_ms);
  };
  row("shadow map", true, t.shadow_map, t.shadow_map, t.shadow_map);
  row("G-buffer", true, t.gbuffer, t.gbuffer, t.gbuffer);
  row("classification (GPU)", false, 0, 0, t.classification);
  if (r.run.path == "cpu")
    row("index build (CPU)", false, 0, 0, t.index_build_cpu);
  else
    row("index build (GPU)", false, 0, 0, t.index_build_gpu);
  row("global light", true, t.naive_light, t.dynamic_light, t.tiled_light);
  row("light total", true, t.naive_light, t.dynamic_light, classified_light);
  auto speedup = [&](const char* baseline, double baseline_ms) {
    const double ratio = classified_light > 0 ? baseline_ms / classified_light : 0.0;
    out += fmt::format("speed-up of the light pass vs {}: {:.2f}x ({} / classification + index build + tiled light)\n",
                       baseline, ratio, baseline);
  };
  if (naive) speedup("naive", t.naive_light);
  if (dynamic) speedup("dynamic", t.dynamic_light);
  if (r.run.light_pass == "compute") {
    out += fmt::format("tiles {}, dispatched in {} workgroups", r.tiles, r.primitives_coalesced);
  } else {
    out += fmt::format("tiles {}, {} {} -> {} coalesced ({} rectangles)", r.tiles, r.run.primitive,
                       r.primitives_uncoalesced, r.primitives_coalesced, r.rectangles);
  }
  out += fmt::format("; classified vs {}: {} pixels differ (max {:.3g})", r.equivalence.reference,
                     r.equivalence.classified.pixels_different, r.equivalence.classified.max_abs_difference);
  if (r.equivalence.dynamic) {
    out += fmt::format("; dynamic vs naive: {} differ (max {:.3g})", r.equivalence.dynamic->pixels_different,
                       r.equivalence.dynamic->max_abs_difference);
  }
  return out + "\n";
}

}  // namespace tilelight::app
