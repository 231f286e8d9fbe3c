#include "sweep_tables.h"

#include "gbuffer_bound.h"

#include <fmt/format.h>
#include <median/median.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace tilelight::sweep {
namespace {

std::string ms(double value) { return fmt::format("{:.3f}", value); }

std::string configurations_table(const Comparison& c, const std::vector<const Measurement*>& rows) {
  std::string out =
      "| configuration | tiles | primitives drawn | classification | index build | tiled light | "
      "classified total | naive light | speed-up | pixels differ |\n"
      "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Measurement* m : rows) {
    out += fmt::format("| {} | {} | {} | {} | {} ({}) | {} | {} | {} | {:.2f}x | {} |\n", row_label(c.facet, *m),
                       m->tiles, m->primitives_coalesced, ms(m->timings.classification), ms(m->index_build()),
                       m->options.path == IndexPath::gpu ? "GPU" : "CPU", ms(m->timings.tiled_light),
                       ms(m->classified_light()), ms(m->timings.naive_light), m->speedup(),
                       m->equivalence.pixels_different);
  }
  return out;
}

// Table 4.2 of the chapter: the tasks the two methods differ in, and their totals.
std::string stages_table(const Measurement& m) {
  const app::MedianTimings& t = m.timings;
  const bool gpu = m.options.path == IndexPath::gpu;
  std::string out = "| task (ms) | naive | classification |\n|---|---:|---:|\n";
  out += fmt::format("| tile classification (GPU) | 0.000 | {} |\n", ms(t.classification));
  out += fmt::format("| index build ({}) | 0.000 | {} |\n", gpu ? "GPU" : "CPU", ms(m.index_build()));
  out += fmt::format("| global light pass | {} | {} |\n", ms(t.naive_light), ms(t.tiled_light));
  out += fmt::format("| **total** | **{}** | **{}** |\n", ms(t.naive_light), ms(m.classified_light()));
  out += fmt::format(
      "\nSpeed-up {:.2f}x; classification is {:.1f}% of the naive pass. Shared by both frames and not in "
      "the totals: shadow map {} ms, G-buffer {} ms. Classified vs naive: {} pixels differ.\n",
      m.speedup(), t.naive_light > 0 ? 100.0 * t.classification / t.naive_light : 0.0, ms(t.shadow_map), ms(t.gbuffer),
      m.equivalence.pixels_different);
  return out;
}

std::string min_median_max(const std::vector<double>& values) {
  if (values.empty()) return "-";
  return fmt::format("{:.2f}x / {:.2f}x / {:.2f}x", *std::min_element(values.begin(), values.end()), median::of(values),
                     *std::max_element(values.begin(), values.end()));
}

// The camera column: its name, and "(no cull)" where batch culling was off (sweep --cull off).
std::string camera_cell(const RendererOptions& o) { return o.cull_batches ? o.camera : o.camera + " (no cull)"; }

// The row groups of the baseline tables: rows that differ only in their camera.
std::string group_name(const RendererOptions& o, std::uint32_t msaa_samples) {
  return fmt::format("{}, {}x MSAA, {}x{}, {} index build{}", to_string(o.light_pass), msaa_samples, o.width, o.height,
                     o.path == IndexPath::gpu ? "GPU" : "CPU", o.cull_batches ? "" : ", no cull");
}

// Classified vs dynamic vs naive per row, then per MSAA mode and size the spread over cameras.
std::string baselines_table(const std::vector<const Measurement*>& rows) {
  std::string out =
      "| light pass | MSAA | size | camera | sky tiles | naive light | dynamic light | classification | index build | "
      "tiled light | classified total | vs naive | vs dynamic | pixels differ (classified, dynamic) |\n"
      "|---|---:|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  // (MSAA, size) -> speed-ups over the cameras, in row order.
  std::vector<std::pair<std::string, std::pair<std::vector<double>, std::vector<double>>>> groups;
  for (const Measurement* m : rows) {
    const RendererOptions& o = m->options;
    const bool gpu = o.path == IndexPath::gpu;
    out += fmt::format(
        "| {} | {}x | {}x{} | {} | {:.0f} % | {} | {} | {} | {} ({}) | {} | {} | {:.2f}x | {:.2f}x | {}, {} |\n",
        to_string(o.light_pass), m->msaa_samples, o.width, o.height, camera_cell(o),
        m->tiles > 0 ? 100.0 * m->sky_tiles / m->tiles : 0.0, ms(m->timings.naive_light), ms(m->timings.dynamic_light),
        ms(m->timings.classification), ms(m->index_build()), gpu ? "GPU" : "CPU", ms(m->timings.tiled_light),
        ms(m->classified_light()), m->speedup(), m->speedup_over_dynamic(), m->equivalence.pixels_different,
        m->dynamic_equivalence.pixels_different);
    const std::string group = group_name(o, m->msaa_samples);
    if (groups.empty() || groups.back().first != group) groups.push_back({group, {}});
    groups.back().second.first.push_back(m->speedup());
    groups.back().second.second.push_back(m->speedup_over_dynamic());
  }
  out +=
      "\nSpeed-up of the classified light path over the cameras, min / median / max:\n\n"
      "| light pass, MSAA, size | cameras | vs naive | vs dynamic |\n|---|---:|---|---|\n";
  for (const auto& [group, speedups] : groups) {
    out += fmt::format("| {} | {} | {} | {} |\n", group, speedups.first.size(), min_median_max(speedups.first),
                       min_median_max(speedups.second));
  }
  return out;
}

// SKY and LIGHT_SCATTERING as variants, specialization constants and branches: what each build
// costs (blobs and shadergen's time, pipelines and their creation) and what its tile pass takes.
std::string kinds_table(const std::vector<const Measurement*>& rows) {
  std::string out =
      "| light pass | kinds | SPIR-V blobs (sources) | shadergen build (s) | pipelines | pipeline creation (ms) | "
      "tiled light (ms) | classified light path (ms) | pixels differ |\n"
      "|---|---|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Measurement* m : rows) {
    const RendererOptions& o = m->options;
    out += fmt::format(
        "| {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", to_string(o.light_pass), to_string(o.light_kinds),
        m->spec_build ? fmt::format("{} ({})", m->spec_build->blobs, m->spec_build->sources) : "-",
        m->spec_build ? fmt::format("{:.2f}", m->spec_build->seconds) : "-", m->pipelines, ms(m->tile_pipelines_ms),
        ms(m->timings.tiled_light), ms(m->classified_light()), m->equivalence.pixels_different);
  }
  return out;
}

// A time that was not measured reads 0 (a pass that did not run, a field the renderer does not
// fill): "-" rather than a figure that looks like a very fast pass.
std::string ms_or_dash(double value) { return value > 0 ? ms(value) : "-"; }

std::string ratio_or_dash(const std::optional<app::RatioStats>& ratio) {
  return ratio ? fmt::format("{:.2f}x", ratio->median) : "-";
}

std::string index_build_name(const RendererOptions& o) { return o.path == IndexPath::gpu ? "GPU" : "CPU"; }

// The per-frame-ratio medians of one row group (light pass, MSAA, size, index build) over its
// cameras, and the G-buffer bytes every row of it reads.
struct RatioGroup {
  std::string name;
  std::size_t cameras = 0;
  std::uint64_t gbuffer_bytes = 0;
  std::vector<double> light_naive, light_dynamic, frame_naive, frame_dynamic;

  void add(const app::FrameRatios& r) {
    ++cameras;
    for (const auto& [ratio, into] : {std::pair{&r.light_vs_naive, &light_naive},
                                      {&r.light_vs_dynamic, &light_dynamic},
                                      {&r.whole_frame_vs_naive, &frame_naive},
                                      {&r.whole_frame_vs_dynamic, &frame_dynamic}}) {
      if (*ratio) into->push_back((*ratio)->median);
    }
  }
};

// The device's name is on the run line above the table.
std::string bound_heading(std::optional<double> bytes_per_second) {
  if (!bytes_per_second) return "limit (bandwidth unknown)";
  return fmt::format("limit at {:.2f} TB/s", *bytes_per_second / 1e12);
}

std::string bound_cell(std::uint64_t bytes, std::optional<double> bytes_per_second) {
  const std::optional<double> bound = gbuffer_read_bound_ms(bytes, bytes_per_second);
  return bound ? ms(*bound) : "unknown";
}

// Classified vs naive, dynamic and floor per row, light path and whole frame, with the
// per-frame ratios; then per group the spread over the cameras beside the G-buffer-read limit.
std::string whole_frame_table(const std::vector<const Measurement*>& rows, std::string_view device_name) {
  std::string out =
      "| light pass | MSAA | size | index build | camera | classified light | naive light | dynamic light | "
      "floor light | classified frame | naive frame | dynamic frame | light vs naive | light vs dynamic | "
      "frame vs naive | frame vs dynamic | pixels differ (classified, dynamic) |\n"
      "|---|---:|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  std::vector<RatioGroup> groups;
  for (const Measurement* m : rows) {
    const RendererOptions& o = m->options;
    const app::MedianTimings& t = m->timings;
    const app::FrameRatios r = m->ratios();
    out +=
        fmt::format("| {} | {}x | {}x{} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {}, {} |\n",
                    to_string(o.light_pass), m->msaa_samples, o.width, o.height, index_build_name(o), camera_cell(o),
                    ms_or_dash(m->classified_light()), ms_or_dash(t.naive_light), ms_or_dash(t.dynamic_light),
                    ms_or_dash(t.floor_light), ms_or_dash(t.frame_classified), ms_or_dash(t.frame_naive),
                    ms_or_dash(t.frame_dynamic), ratio_or_dash(r.light_vs_naive), ratio_or_dash(r.light_vs_dynamic),
                    ratio_or_dash(r.whole_frame_vs_naive), ratio_or_dash(r.whole_frame_vs_dynamic),
                    m->equivalence.pixels_different, m->dynamic_equivalence.pixels_different);
    const std::string group = group_name(o, m->msaa_samples);
    if (groups.empty() || groups.back().name != group) {
      groups.push_back({group, 0, gbuffer_bytes(o.width, o.height, m->msaa_samples), {}, {}, {}, {}});
    }
    groups.back().add(r);
  }
  const std::optional<double> bandwidth = memory_bandwidth(device_name);
  out += fmt::format(
      "\nRatios are per frame (the baseline's time over the classified one in the same frame, median over the "
      "frames); light: classification + index build + tiled light against the baseline's light pass; frame: the "
      "classified frame end to end against the baseline's whole frame. \"-\": not measured.\n\n"
      "Over the cameras, min / median / max of those medians. A full-frame light pass reads the whole G-buffer "
      "(pixels x samples x {} bytes) at least once: that read at the device's peak memory bandwidth is the "
      "least any light pass can take.\n\n"
      "| light pass, MSAA, size | cameras | light vs naive | light vs dynamic | frame vs naive | frame vs dynamic | "
      "G-buffer read | {} |\n|---|---:|---|---|---|---|---:|---:|\n",
      kGBufferBytesPerSample, bound_heading(bandwidth));
  for (const RatioGroup& g : groups) {
    out += fmt::format("| {} | {} | {} | {} | {} | {} | {:.1f} MB | {} |\n", g.name, g.cameras,
                       min_median_max(g.light_naive), min_median_max(g.light_dynamic), min_median_max(g.frame_naive),
                       min_median_max(g.frame_dynamic), static_cast<double>(g.gbuffer_bytes) / 1e6,
                       bound_cell(g.gbuffer_bytes, bandwidth));
  }
  return out;
}

}  // namespace

std::string markdown_table(const Comparison& comparison, const std::vector<const Measurement*>& rows,
                           std::string_view device_name) {
  if (comparison.facet == Facet::stages && !rows.empty()) return stages_table(*rows.front());
  if (comparison.facet == Facet::kinds) return kinds_table(rows);
  if (comparison.facet == Facet::baselines && !rows.empty()) {
    // The whole-frame layout where the floor ran too; the light-path one, as before, otherwise.
    if (rows.front()->options.baselines == Baselines::all) return whole_frame_table(rows, device_name);
    return baselines_table(rows);
  }
  return configurations_table(comparison, rows);
}

}  // namespace tilelight::sweep
