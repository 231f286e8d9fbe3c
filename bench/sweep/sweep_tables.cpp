#include "sweep_tables.h"

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
  return fmt::format("{:.2f}x / {:.2f}x / {:.2f}x", *std::min_element(values.begin(), values.end()), median::of(values),
                     *std::max_element(values.begin(), values.end()));
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
        to_string(o.light_pass), m->msaa_samples, o.width, o.height, o.camera,
        m->tiles > 0 ? 100.0 * m->sky_tiles / m->tiles : 0.0, ms(m->timings.naive_light), ms(m->timings.dynamic_light),
        ms(m->timings.classification), ms(m->index_build()), gpu ? "GPU" : "CPU", ms(m->timings.tiled_light),
        ms(m->classified_light()), m->speedup(), m->speedup_over_dynamic(), m->equivalence.pixels_different,
        m->dynamic_equivalence.pixels_different);
    const std::string group = fmt::format("{}, {}x MSAA, {}x{}, {} index build", to_string(o.light_pass),
                                          m->msaa_samples, o.width, o.height, gpu ? "GPU" : "CPU");
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

}  // namespace

std::string markdown_table(const Comparison& comparison, const std::vector<const Measurement*>& rows) {
  if (comparison.facet == Facet::stages && !rows.empty()) return stages_table(*rows.front());
  if (comparison.facet == Facet::baselines && !rows.empty()) return baselines_table(rows);
  return configurations_table(comparison, rows);
}

}  // namespace tilelight::sweep
