#include "sweep_charts.h"

#include <fmt/format.h>

namespace tilelight::sweep {
namespace {

constexpr const char* kValueAxis = "median time per frame (ms)";

// Each quantity keeps its colour in every chart.
Rgba8 colour(std::size_t palette_index) { return plot::series_colour(palette_index); }
const Rgba8 kClassified = colour(3);
const Rgba8 kNaive = colour(4);
const Rgba8 kDynamic = colour(5);

std::string with_speedup(const Comparison& c, const Measurement& m) {
  return fmt::format("{}: {:.2f}x", row_label(c.facet, m), m.speedup());
}

plot::BarChart stage_breakdown(const Comparison& c, const std::vector<const Measurement*>& rows) {
  plot::BarChart chart;
  chart.title = c.title;
  chart.category_axis = "configuration: speed-up";
  chart.value_axis = kValueAxis;
  chart.series = {"classification", "index build", "tiled light", "classified total", "naive light"};
  chart.colours = {colour(0), colour(1), colour(2), kClassified, kNaive};
  for (const Measurement* m : rows) {
    chart.categories.push_back(with_speedup(c, *m));
    chart.values.push_back({m->timings.classification, m->index_build(), m->timings.tiled_light, m->classified_light(),
                            m->timings.naive_light});
  }
  return chart;
}

plot::BarChart totals_per_size(const Comparison& c, const std::vector<const Measurement*>& rows) {
  plot::BarChart chart;
  chart.title = c.title;
  chart.category_axis = "frame size: speed-up";
  chart.value_axis = kValueAxis;
  chart.series = {"classified (classification + index build + tiled light)", "naive light"};
  chart.colours = {kClassified, kNaive};
  for (const Measurement* m : rows) {
    chart.categories.push_back(with_speedup(c, *m));
    chart.values.push_back({m->classified_light(), m->timings.naive_light});
  }
  return chart;
}

plot::BarChart three_methods(const Comparison& c, const std::vector<const Measurement*>& rows) {
  plot::BarChart chart;
  chart.title = c.title;
  chart.category_axis = "MSAA, size, camera: speed-up over naive / over dynamic";
  chart.value_axis = kValueAxis;
  chart.series = {"classified (classification + index build + tiled light)", "dynamic light", "naive light"};
  chart.colours = {kClassified, kDynamic, kNaive};
  for (const Measurement* m : rows) {
    chart.categories.push_back(
        fmt::format("{}: {:.2f}x / {:.2f}x", row_label(c.facet, *m), m->speedup(), m->speedup_over_dynamic()));
    chart.values.push_back({m->classified_light(), m->timings.dynamic_light, m->timings.naive_light});
  }
  return chart;
}

plot::BarChart table_4_2(const Comparison& c, const Measurement& m) {
  plot::BarChart chart;
  chart.title = fmt::format("{}: {:.2f}x", c.title, m.speedup());
  chart.category_axis = "task";
  chart.value_axis = kValueAxis;
  chart.series = {"naive", "classification"};
  chart.colours = {kNaive, kClassified};
  chart.categories = {"tile classification",
                      m.options.path == IndexPath::gpu ? "index build (GPU)" : "index build (CPU)", "global light pass",
                      "total"};
  chart.values = {{0.0, m.timings.classification},
                  {0.0, m.index_build()},
                  {m.timings.naive_light, m.timings.tiled_light},
                  {m.timings.naive_light, m.classified_light()}};
  return chart;
}

}  // namespace

plot::BarChart comparison_chart(const Comparison& comparison, const std::vector<const Measurement*>& rows) {
  switch (comparison.facet) {
    case Facet::resolution: return totals_per_size(comparison, rows);
    case Facet::stages: return table_4_2(comparison, *rows.front());
    case Facet::baselines: return three_methods(comparison, rows);
    default: return stage_breakdown(comparison, rows);
  }
}

}  // namespace tilelight::sweep
