#include "tilelight/app/report.h"

#include "option_names.h"
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

// Every timed stage and whole frame, by its report.json name, in the report's order.
constexpr std::array<std::pair<const char*, double FrameTimings::*>, 16> kStages{{
    {"gbuffer", &FrameTimings::gbuffer},
    {"gbuffer_plain", &FrameTimings::gbuffer_plain},
    {"shadow_map", &FrameTimings::shadow_map},
    {"classification", &FrameTimings::classification},
    {"index_build_cpu", &FrameTimings::index_build_cpu},
    {"index_build_gpu", &FrameTimings::index_build_gpu},
    {"tiled_light", &FrameTimings::tiled_light},
    {"naive_light", &FrameTimings::naive_light},
    {"dynamic_light", &FrameTimings::dynamic_light},
    {"floor_light", &FrameTimings::floor_light},
    {"local_lights", &FrameTimings::local_lights},
    {"forward", &FrameTimings::forward},
    {"local_light_shadows", &FrameTimings::local_light_shadows},
    {"frame_classified", &FrameTimings::frame_classified},
    {"frame_naive", &FrameTimings::frame_naive},
    {"frame_dynamic", &FrameTimings::frame_dynamic},
}};

nlohmann::ordered_json equivalence_json(const Equivalence& e) {
  return {{"max_abs_difference", e.max_abs_difference}, {"pixels_different", e.pixels_different}};
}

nlohmann::ordered_json ratio_json(const std::optional<RatioStats>& r) {
  if (!r) return nullptr;
  return {{"median", round3(r->median)}, {"min", round3(r->min)}, {"max", round3(r->max)}};
}

nlohmann::ordered_json ratios_json(const FrameRatios& r) {
  return {{"whole_frame_vs_dynamic", ratio_json(r.whole_frame_vs_dynamic)},
          {"whole_frame_vs_naive", ratio_json(r.whole_frame_vs_naive)},
          {"light_vs_dynamic", ratio_json(r.light_vs_dynamic)},
          {"light_vs_naive", ratio_json(r.light_vs_naive)}};
}

}  // namespace

std::vector<std::uint8_t> optimised_tile_ids(const std::vector<std::uint8_t>& raw_ids) {
  std::vector<std::uint8_t> out(raw_ids.size());
  for (std::size_t i = 0; i < raw_ids.size(); ++i) {
    const std::optional<split_second::OptimisedId> id = split_second::optimised_id(split_second::RawId(raw_ids[i]));
    if (!id) {
      throw Error(
          fmt::format("tile {}: raw ID {} is {}", i, raw_ids[i],
                      raw_ids[i] < split_second::kRawCount ? "impossible (a pruned class)" : "out of range (0..127)"));
    }
    out[i] = static_cast<std::uint8_t>(id->value());
  }
  return out;
}

void count_tiles(FrameReport& report, const std::vector<std::uint8_t>& raw_ids) {
  report.tiles = static_cast<std::uint32_t>(raw_ids.size());
  report.raw_property_tiles.clear();
  // The generated registry's features: each a one-bit property, named as the shaders' define
  // (SOLID_SHADOW, which the spec's feature SHADOW_SOLID switches on), as the docs name them.
  for (const shadergen::Feature& feature : split_second::kFeatures) {
    const std::uint32_t mask = ((1u << feature.width) - 1u) << feature.bit;
    const auto count =
        std::count_if(raw_ids.begin(), raw_ids.end(), [mask](std::uint8_t id) { return (id & mask) != 0; });
    report.raw_property_tiles.emplace_back(std::string(feature.define), static_cast<std::uint32_t>(count));
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
  j["path"] = name_of(path_names(), r.run.path);
  j["permutations"] = name_of(permutation_names(), r.run.raw_permutations);
  j["camera"] = r.run.camera;
  const CameraPose& pose = r.run.camera_pose;
  j["camera_pose"] = {{"eye", pose.eye}, {"target", pose.target}, {"up", pose.up}, {"fov_deg", pose.fov_deg}};
  // The --scene file's name, or null for the procedural scene; the triangles of either.
  j["scene"] = r.run.scene.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(r.run.scene);
  j["scene_triangles"] = r.run.scene_triangles;
  // The lines "warning: FILE: ..." printed on stderr; [] for the procedural scene.
  j["scene_warnings"] = r.run.scene_warnings;
  // The scene's local lights by type: --lights N's, or a --scene file's KHR_lights_punctual ones.
  j["local_lights"] = {
      {"point", r.run.local_lights.point}, {"spot", r.run.local_lights.spot}, {"box", r.run.local_lights.box}};
  j["load_ms"] = std::round(r.load_ms * 100.0) / 100.0;
  // Mesh batches wholly outside a pass's clip volume, not drawn (--no-cull: 0, and "cull": false).
  j["cull"] = r.run.cull;
  j["culled"] = {{"gbuffer_batches", r.culled.gbuffer}, {"shadow_batches", r.culled.shadow}};
  j["coalesce"] = r.run.coalesce;
  j["primitive"] = r.run.primitive;
  j["baselines"] = name_of(baseline_names(), r.run.baselines);
  j["light_pass"] = name_of(light_pass_names(), r.run.light_pass);
  // Which build of the light domain the tile pass drew (--light-kinds), its pipelines and the
  // host time their creation took when the renderer was made.
  j["light_kinds"] = name_of(light_kinds_names(), r.run.light_kinds);
  j["tile_pipelines"] = {{"count", r.run.tile_pipelines},
                         {"create_ms", std::round(r.run.tile_pipelines_ms * 1000.0) / 1000.0}};
  j["local_light_pass"] = name_of(local_light_pass_names(), r.run.local_light_pass);
  // The forward pass of the blended materials: instances drawn per light target, and K.
  j["forward"] = {{"instances", r.run.forward_instances}, {"max_lights", kForwardMaxLights}};
  // The local lights' shadow maps (docs/local-lights.md, "Shadows"): the pool's faces and memory,
  // its cap, and the lights that cast shadows but got no map (over the cap).
  const LocalLightShadowPool& shadows = r.local_light_shadows;
  j["local_light_shadows"] = {{"enabled", shadows.enabled},     {"cached", shadows.cached},
                              {"maps", shadows.maps},           {"faces", shadows.faces},
                              {"face_size", shadows.face_size}, {"bytes", shadows.bytes},
                              {"cap_bytes", shadows.cap_bytes}, {"unshadowed", shadows.unshadowed}};
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
  // Baseline over classified, frame by frame (frame_ratios.h); null where the baseline did not run.
  j["ratios"] = ratios_json(r.ratios);
  // `equivalence`: the classified frame against `reference`; `dynamic_equivalence`: the dynamic
  // frame against the naive one (null unless both ran). Both null when neither ran.
  j["equivalence"] = nullptr;
  j["dynamic_equivalence"] = nullptr;
  if (r.equivalence) {
    j["equivalence"] = equivalence_json(r.equivalence->classified);
    j["equivalence"]["reference"] = r.equivalence->reference;
    if (r.equivalence->dynamic) j["dynamic_equivalence"] = equivalence_json(*r.equivalence->dynamic);
  }
  j["process"] = {{"peak_rss_mib", std::round(r.process.peak_rss_mib * 10.0) / 10.0},
                  {"rss_after_frames_mib", std::round(r.process.rss_after_frames_mib * 10.0) / 10.0}};
  return j.dump(2) + "\n";
}

namespace {

// One column per full-frame pass that ran, then the classified frame.
struct Column {
  const char* name;
  double FrameTimings::*light;  // its light pass
  double FrameTimings::*frame;  // its whole frame; null: the floor, which has none of its own
};

std::vector<Column> baseline_columns(Baselines b) {
  std::vector<Column> columns;
  if (runs_naive(b)) columns.push_back({"naive", &FrameTimings::naive_light, &FrameTimings::frame_naive});
  if (runs_dynamic(b)) columns.push_back({"dynamic", &FrameTimings::dynamic_light, &FrameTimings::frame_dynamic});
  if (runs_floor(b)) columns.push_back({"floor", &FrameTimings::floor_light, nullptr});
  return columns;
}

// The median whole frame of a column; the floor's, which no report key holds, is the sum of its
// passes' medians (what the floor pass would add to the plain frame).
double whole_frame_ms(const MedianTimings& t, const Column& c) {
  return c.frame ? t.*c.frame : t.shadow_map + t.gbuffer_plain + t.*c.light;
}

std::string run_lines(const RunDescription& run) {
  std::string out = fmt::format(
      "{}x{}, {}x MSAA, {}, {} light pass, path {}, {} permutations, camera {}, median of {} frame(s)\n", run.width,
      run.height, run.msaa_samples, run.device, to_string(run.light_pass), name_of(path_names(), run.path),
      name_of(permutation_names(), run.raw_permutations), run.camera, run.frames);
  // The variant build is the default and the line stays as it always was; another build says so.
  if (run.light_kinds != LightKinds::variant) {
    out += fmt::format(
        "light kinds {}: SKY and LIGHT_SCATTERING as {}, {} tile-pass pipelines\n", to_string(run.light_kinds),
        run.light_kinds == LightKinds::branch ? "run-time branches" : "specialization constants", run.tile_pipelines);
  }
  return out +
         fmt::format("scene {} ({} triangles)\n", run.scene.empty() ? "procedural" : run.scene, run.scene_triangles);
}

// The whole frame, then its stages: a column per baseline (each on the plain G-buffer), the
// classified frame last.
std::string stage_rows(const FrameReport& r) {
  const MedianTimings& t = r.timings;
  const std::vector<Column> columns = baseline_columns(r.run.baselines);
  const std::string none = "-";
  std::string out = fmt::format("{:<28}", "stage (ms)");
  for (const Column& c : columns) out += fmt::format("{:>12}", c.name);
  out += fmt::format("{:>14}\n", "classified");
  // `baseline`: the column's figure, or nullopt for "-"; `classified` likewise.
  auto row = [&](const char* name, auto baseline, std::optional<double> classified) {
    out += fmt::format("{:<28}", name);
    for (const Column& c : columns) {
      const std::optional<double> ms = baseline(c);
      out += fmt::format("{:>12}", ms ? fmt::format("{:.3f}", *ms) : none);
    }
    out += fmt::format("{:>14}\n", classified ? fmt::format("{:.3f}", *classified) : none);
  };
  auto same = [](double ms) { return [ms](const Column&) -> std::optional<double> { return ms; }; };
  auto nothing = [](const Column&) -> std::optional<double> { return std::nullopt; };
  auto light = [&](const Column& c) -> std::optional<double> { return t.*c.light; };
  auto frame = [&](const Column& c) -> std::optional<double> { return whole_frame_ms(t, c); };
  // The whole frame first: a baseline's is the sum of its passes; the classified one is end to
  // end (its host round trip included), so it may exceed the sum of its rows below.
  row("whole frame", frame, t.frame_classified);
  row("shadow map", same(t.shadow_map), t.shadow_map);
  row("G-buffer, plain (baselines)", same(t.gbuffer_plain), std::nullopt);
  row("G-buffer, classified", nothing, t.gbuffer);
  row("classification (GPU)", nothing, t.classification);
  if (r.run.path == IndexPath::cpu) {
    row("index build (CPU)", nothing, t.index_build_cpu);
  } else {
    row("index build (GPU)", nothing, t.index_build_gpu);
  }
  row("global light", light, t.tiled_light);
  row("light path", light, classified_light_ms(t));
  return out;
}

std::string ratio_line(const char* what, const char* baseline, const std::optional<RatioStats>& r) {
  if (!r) return "";
  return fmt::format("{} vs {}: {:.2f}x median ({:.2f}x\u2013{:.2f}x over the frames)\n", what, baseline, r->median,
                     r->min, r->max);
}

std::string speedup_lines(const FrameReport& r) {
  const char* naive = "naive (every feature on every sample)";
  const char* dynamic = "dynamic (per-pixel branching)";
  return ratio_line("whole frame", dynamic, r.ratios.whole_frame_vs_dynamic) +
         ratio_line("whole frame", naive, r.ratios.whole_frame_vs_naive) +
         ratio_line("light path", dynamic, r.ratios.light_vs_dynamic) +
         ratio_line("light path", naive, r.ratios.light_vs_naive);
}

std::string comparison_text(const FrameReport& r) {
  if (!r.equivalence) return "; no comparison ran (neither the naive nor the dynamic pass ran)";
  std::string out =
      fmt::format("; classified vs {}: {} pixels differ (max {:.3g})", r.equivalence->reference,
                  r.equivalence->classified.pixels_different, r.equivalence->classified.max_abs_difference);
  if (r.equivalence->dynamic) {
    out += fmt::format("; dynamic vs naive: {} differ (max {:.3g})", r.equivalence->dynamic->pixels_different,
                       r.equivalence->dynamic->max_abs_difference);
  }
  return out;
}

}  // namespace

std::string timing_table(const FrameReport& r) {
  std::string out = run_lines(r.run) + stage_rows(r) + speedup_lines(r);
  if (r.run.light_pass == LightPass::compute) {
    out += fmt::format("tiles {}, dispatched in {} workgroups", r.tiles, r.primitives_coalesced);
  } else {
    out += fmt::format("tiles {}, {} {} -> {} coalesced ({} rectangles)", r.tiles, r.run.primitive,
                       r.primitives_uncoalesced, r.primitives_coalesced, r.rectangles);
  }
  return out + comparison_text(r) + "\n";
}

}  // namespace tilelight::app
