#pragma once
// A grouped horizontal bar chart drawn with the project's bitmap font and written as a PNG,
// reproducible byte for byte. Not gnuplot-nox or python3-matplotlib (both are Debian 12
// packages): each would put a second program, its version and its fonts between the sweep and
// the committed charts, on every machine that runs the sweep's smoke test, to replace ~250 lines.
//
// Layout, top to bottom: the title; the legend (one swatch and name per series, one line); one
// group of bars per category (category name at the left, one bar per series, each bar's value
// printed at its end); the value axis with "nice" ticks (1, 2 or 5 times a power of ten) and
// vertical grid lines; the value-axis label. The category-axis label stands above the category
// names. Bars start at zero; every value must be finite and >= 0.

#include "tilelight/picture/rgba8_canvas.h"

#include <string>
#include <vector>

namespace tilelight::plot {

struct BarChart {
  std::string title;
  std::string category_axis;  // e.g. "configuration"
  std::string value_axis;     // e.g. "median time (ms)"
  std::vector<std::string> categories;
  std::vector<std::string> series;
  std::vector<std::vector<double>> values;  // values[category][series]
  int decimals = 2;                         // digits after the point in the bar value labels
  // One colour per series, so a quantity keeps its colour across charts; empty = the palette
  // in order (series_colour).
  std::vector<Rgba8> colours;
};

// Where the value axis puts its ticks: 0, step, 2 step, ... up to `max` (a multiple of step
// >= the largest value). An all-zero chart gets the range 0..1.
struct ValueAxis {
  double step = 1;
  double max = 1;
};
ValueAxis nice_value_axis(double largest_value);

// Throws tilelight::Error, messages exactly:
//   "bar chart '<title>': no categories" / "... no series"
//   "bar chart '<title>': <n> rows of values for <m> categories"
//   "bar chart '<title>': <n> colours for <m> series"
//   "bar chart '<title>': category <i> has <n> values, expected <m>"
//   "bar chart '<title>': value <v> of category '<c>', series '<s>' is not finite and >= 0"
void check_bar_chart(const BarChart& chart);

// Draws the chart on a white canvas sized to fit it. Checks it first (check_bar_chart).
Rgba8Canvas draw_bar_chart(const BarChart& chart);

// The colour of series `index` (a colour-blind-safe palette, repeating after 7 series).
Rgba8 series_colour(std::size_t index);

}  // namespace tilelight::plot
