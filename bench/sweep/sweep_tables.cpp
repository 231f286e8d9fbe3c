#include "sweep_tables.h"

#include <fmt/format.h>

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
      m.speedup(), t.naive_light > 0 ? 100.0 * t.classification / t.naive_light : 0.0, ms(t.shadow_map),
      ms(t.gbuffer), m.equivalence.pixels_different);
  return out;
}

}  // namespace

std::string markdown_table(const Comparison& comparison, const std::vector<const Measurement*>& rows) {
  if (comparison.facet == Facet::stages && !rows.empty()) return stages_table(*rows.front());
  return configurations_table(comparison, rows);
}

}  // namespace tilelight::sweep
