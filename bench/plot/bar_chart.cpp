#include "bar_chart.h"

#include "tilelight/base/error.h"
#include "tilelight/picture/bitmap_font.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace tilelight::plot {
namespace {

constexpr int kTextScale = 2;  // body text: 12 x 18 pixel cells, legible at full-page width
constexpr int kTitleScale = 3;
constexpr int kMargin = 24;
constexpr int kPlotWidth = 640;  // the longest possible bar
constexpr int kBarHeight = 22;
constexpr int kBarGap = 2;     // between the bars of one group
constexpr int kGroupGap = 18;  // between groups
constexpr int kSwatch = 18;
constexpr int kTickLength = 6;

constexpr Rgba8 kBackground{255, 255, 255, 255};
constexpr Rgba8 kInk{30, 30, 30, 255};
constexpr Rgba8 kGrid{225, 225, 225, 255};
constexpr Rgba8 kAxis{90, 90, 90, 255};

Rgba8 colour_of(const BarChart& chart, std::size_t series) {
  return chart.colours.empty() ? series_colour(series) : chart.colours[series];
}

int text_w(const std::string& text, int scale = kTextScale) { return text_width(text, scale); }
int line_h(int scale = kTextScale) { return text_height(scale); }

int group_height(std::size_t series) {
  return static_cast<int>(series) * kBarHeight + static_cast<int>(series - 1) * kBarGap;
}

std::string value_label(double value, int decimals) { return fmt::format("{:.{}f}", value, decimals); }

// Enough digits to tell the ticks apart: none for steps >= 1, one for 0.5, two for 0.02, ...
std::string tick_label(double value, double step) {
  const int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9)));
  return fmt::format("{:.{}f}", value, decimals);
}

int legend_width(const BarChart& chart) {
  int width = 0;
  for (const std::string& name : chart.series) width += kSwatch + 6 + text_w(name) + 24;
  return width;
}

// Every measure the drawing needs, worked out once from the chart.
struct Layout {
  ValueAxis axis;
  int title_y = kMargin;
  int legend_y = 0;
  int category_axis_y = 0;
  int groups_y = 0;
  int label_x = kMargin;  // category names
  int plot_x = 0;         // value 0
  int axis_y = 0;         // the value axis line
  int tick_label_y = 0;
  int value_axis_label_y = 0;
  int width = 0, height = 0;
};

Layout make_layout(const BarChart& chart) {
  Layout l;
  double largest = 0;
  int widest_value = 0;
  for (const auto& row : chart.values) {
    for (double v : row) {
      largest = std::max(largest, v);
      widest_value = std::max(widest_value, text_w(value_label(v, chart.decimals)));
    }
  }
  l.axis = nice_value_axis(largest);
  int widest_category = text_w(chart.category_axis);
  for (const std::string& c : chart.categories) widest_category = std::max(widest_category, text_w(c));

  l.legend_y = l.title_y + line_h(kTitleScale) + 12;
  l.category_axis_y = l.legend_y + kSwatch + 20;
  l.groups_y = l.category_axis_y + line_h() + 8;
  l.plot_x = l.label_x + widest_category + 16;
  const int groups = static_cast<int>(chart.categories.size());
  l.axis_y = l.groups_y + groups * group_height(chart.series.size()) + (groups - 1) * kGroupGap + 8;
  l.tick_label_y = l.axis_y + kTickLength + 6;
  l.value_axis_label_y = l.tick_label_y + line_h() + 10;
  l.height = l.value_axis_label_y + line_h() + kMargin;

  // Bars may reach the plot's right end and carry their value label beyond it; the last tick
  // label is centred on that end.
  const int right = l.plot_x + kPlotWidth + std::max(6 + widest_value, text_w(tick_label(l.axis.max, l.axis.step)) / 2);
  l.width =
      std::max({right + kMargin, text_w(chart.title, kTitleScale) + 2 * kMargin, legend_width(chart) + 2 * kMargin,
                l.plot_x + kPlotWidth / 2 + text_w(chart.value_axis) / 2 + kMargin});
  return l;
}

int bar_length(double value, const ValueAxis& axis) {
  return static_cast<int>(std::lround(value / axis.max * kPlotWidth));
}

void draw_legend(Rgba8Canvas& canvas, const BarChart& chart, const Layout& l) {
  int x = kMargin;
  for (std::size_t s = 0; s < chart.series.size(); ++s) {
    canvas.fill_rect(x, l.legend_y, kSwatch, kSwatch, colour_of(chart, s));
    x += kSwatch + 6;
    draw_text(canvas, x, l.legend_y + (kSwatch - line_h()) / 2 + 1, chart.series[s], kInk, kTextScale);
    x += text_w(chart.series[s]) + 24;
  }
}

void draw_value_axis(Rgba8Canvas& canvas, const BarChart& chart, const Layout& l) {
  const int ticks = static_cast<int>(std::lround(l.axis.max / l.axis.step));
  for (int t = 0; t <= ticks; ++t) {
    const double value = t * l.axis.step;
    const int x = l.plot_x + bar_length(value, l.axis);
    canvas.fill_rect(x, l.groups_y - 4, 1, l.axis_y - l.groups_y + 4, kGrid);
    canvas.fill_rect(x, l.axis_y, 1, kTickLength, kAxis);
    const std::string label = tick_label(value, l.axis.step);
    draw_text(canvas, x - text_w(label) / 2, l.tick_label_y, label, kInk, kTextScale);
  }
  canvas.fill_rect(l.plot_x, l.axis_y, kPlotWidth + 1, 1, kAxis);
  canvas.fill_rect(l.plot_x, l.groups_y - 4, 1, l.axis_y - l.groups_y + 4, kAxis);
  draw_text(canvas, l.plot_x + (kPlotWidth - text_w(chart.value_axis)) / 2, l.value_axis_label_y, chart.value_axis,
            kInk, kTextScale);
}

void draw_groups(Rgba8Canvas& canvas, const BarChart& chart, const Layout& l) {
  draw_text(canvas, l.label_x, l.category_axis_y, chart.category_axis, kAxis, kTextScale);
  const int step = group_height(chart.series.size()) + kGroupGap;
  for (std::size_t c = 0; c < chart.categories.size(); ++c) {
    const int top = l.groups_y + static_cast<int>(c) * step;
    const int label_y = top + (group_height(chart.series.size()) - line_h()) / 2;
    draw_text(canvas, l.label_x, label_y, chart.categories[c], kInk, kTextScale);
    for (std::size_t s = 0; s < chart.series.size(); ++s) {
      const double value = chart.values[c][s];
      const int y = top + static_cast<int>(s) * (kBarHeight + kBarGap);
      const int length = bar_length(value, l.axis);
      canvas.fill_rect(l.plot_x + 1, y, length, kBarHeight, colour_of(chart, s));
      draw_text(canvas, l.plot_x + 1 + length + 6, y + (kBarHeight - line_h()) / 2 + 1,
                value_label(value, chart.decimals), kInk, kTextScale);
    }
  }
}

}  // namespace

ValueAxis nice_value_axis(double largest_value) {
  if (!(largest_value > 0)) return {0.2, 1.0};
  // About five ticks: the raw step rounded up to 1, 2 or 5 times a power of ten.
  const double raw = largest_value / 5.0;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double normalised = raw / magnitude;
  const double nice = normalised <= 1 ? 1 : normalised <= 2 ? 2 : normalised <= 5 ? 5 : 10;
  ValueAxis axis;
  axis.step = nice * magnitude;
  axis.max = std::ceil(largest_value / axis.step - 1e-9) * axis.step;
  return axis;
}

void check_bar_chart(const BarChart& chart) {
  const std::string what = "bar chart '" + chart.title + "': ";
  if (chart.categories.empty()) throw Error(what + "no categories");
  if (chart.series.empty()) throw Error(what + "no series");
  if (!chart.colours.empty() && chart.colours.size() != chart.series.size()) {
    throw Error(what + fmt::format("{} colours for {} series", chart.colours.size(), chart.series.size()));
  }
  if (chart.values.size() != chart.categories.size()) {
    throw Error(what +
                fmt::format("{} rows of values for {} categories", chart.values.size(), chart.categories.size()));
  }
  for (std::size_t c = 0; c < chart.values.size(); ++c) {
    if (chart.values[c].size() != chart.series.size()) {
      throw Error(
          what + fmt::format("category {} has {} values, expected {}", c, chart.values[c].size(), chart.series.size()));
    }
    for (std::size_t s = 0; s < chart.series.size(); ++s) {
      const double v = chart.values[c][s];
      if (!std::isfinite(v) || v < 0) {
        throw Error(what + fmt::format("value {} of category '{}', series '{}' is not finite and >= 0", v,
                                       chart.categories[c], chart.series[s]));
      }
    }
  }
}

Rgba8Canvas draw_bar_chart(const BarChart& chart) {
  check_bar_chart(chart);
  const Layout l = make_layout(chart);
  Rgba8Canvas canvas =
      Rgba8Canvas::filled(static_cast<std::uint32_t>(l.width), static_cast<std::uint32_t>(l.height), kBackground);
  draw_text(canvas, kMargin, l.title_y, chart.title, kInk, kTitleScale);
  draw_legend(canvas, chart, l);
  draw_value_axis(canvas, chart, l);
  draw_groups(canvas, chart, l);  // last: bars cover the grid lines
  return canvas;
}

Rgba8 series_colour(std::size_t index) {
  // Okabe and Ito's palette (black left out: it is the text colour).
  static constexpr std::array<Rgba8, 7> kPalette{{{230, 159, 0, 255},
                                                  {86, 180, 233, 255},
                                                  {0, 158, 115, 255},
                                                  {213, 94, 0, 255},
                                                  {0, 114, 178, 255},
                                                  {204, 121, 167, 255},
                                                  {240, 228, 66, 255}}};
  return kPalette[index % kPalette.size()];
}

}  // namespace tilelight::plot
