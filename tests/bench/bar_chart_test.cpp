// The bar chart behind the benchmark plots: axis ranges, bar lengths proportional to the
// values, and exact messages for charts it cannot draw.

#include "plot/bar_chart.h"

#include "tilelight/base/error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace {

using tilelight::Rgba8;
using tilelight::Rgba8Canvas;
using tilelight::plot::BarChart;

BarChart two_bars(double first, double second) {
  BarChart chart;
  chart.title = "t";
  chart.category_axis = "configuration";
  chart.value_axis = "ms";
  chart.categories = {"a", "b"};
  chart.series = {"light"};
  chart.values = {{first}, {second}};
  return chart;
}

// The longest horizontal run of `colour` in any row, per band of rows holding that colour,
// top to bottom: one entry per bar of that colour.
std::vector<int> bar_lengths(const Rgba8Canvas& canvas, Rgba8 colour) {
  std::vector<int> lengths;
  bool in_bar = false;
  for (std::uint32_t y = 0; y < canvas.height; ++y) {
    int run = 0, longest = 0;
    for (std::uint32_t x = 0; x < canvas.width; ++x) {
      run = canvas.pixel(x, y) == colour ? run + 1 : 0;
      longest = std::max(longest, run);
    }
    if (longest > 0 && !in_bar) lengths.push_back(longest);
    if (longest > 0) lengths.back() = std::max(lengths.back(), longest);
    in_bar = longest > 0;
  }
  return lengths;
}

std::string message_of(const BarChart& chart) {
  try {
    (void)tilelight::plot::draw_bar_chart(chart);
  } catch (const tilelight::Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(BarChart, NiceAxisCoversTheLargestValueWithRoundSteps) {
  const auto a = tilelight::plot::nice_value_axis(7.3);
  EXPECT_DOUBLE_EQ(a.step, 2.0);
  EXPECT_DOUBLE_EQ(a.max, 8.0);
  const auto b = tilelight::plot::nice_value_axis(0.042);
  EXPECT_DOUBLE_EQ(b.step, 0.01);
  EXPECT_DOUBLE_EQ(b.max, 0.05);
  const auto c = tilelight::plot::nice_value_axis(100.0);
  EXPECT_DOUBLE_EQ(c.step, 20.0);
  EXPECT_DOUBLE_EQ(c.max, 100.0);
  const auto zero = tilelight::plot::nice_value_axis(0.0);
  EXPECT_DOUBLE_EQ(zero.max, 1.0);
}

TEST(BarChart, BarLengthsAreProportionalToTheValues) {
  // Axis 0..40 (step 10): 10 and 40 are a quarter of the plot and all of it.
  const Rgba8Canvas canvas = tilelight::plot::draw_bar_chart(two_bars(10.0, 40.0));
  const std::vector<int> lengths = bar_lengths(canvas, tilelight::plot::series_colour(0));
  ASSERT_EQ(lengths.size(), 3u);  // the legend swatch, then the two bars
  EXPECT_EQ(lengths[2], 4 * lengths[1]);
  EXPECT_GT(lengths[1], 100);
}

TEST(BarChart, EachSeriesHasItsOwnColour) {
  BarChart chart = two_bars(1.0, 2.0);
  chart.series = {"naive", "classified"};
  chart.values = {{1.0, 0.5}, {2.0, 1.0}};
  const Rgba8Canvas canvas = tilelight::plot::draw_bar_chart(chart);
  EXPECT_NE(tilelight::plot::series_colour(0), tilelight::plot::series_colour(1));
  // Legend swatch + one bar per category, in each colour; the second series' bars are half
  // as long as the first's.
  const std::vector<int> first = bar_lengths(canvas, tilelight::plot::series_colour(0));
  const std::vector<int> second = bar_lengths(canvas, tilelight::plot::series_colour(1));
  ASSERT_EQ(first.size(), 3u);
  ASSERT_EQ(second.size(), 3u);
  EXPECT_EQ(first[2], 2 * second[2]);
}

TEST(BarChart, SeriesTakeTheColoursGiven) {
  BarChart chart = two_bars(1.0, 2.0);
  const Rgba8 grey{128, 128, 128, 255};
  chart.colours = {grey};
  const Rgba8Canvas canvas = tilelight::plot::draw_bar_chart(chart);
  EXPECT_EQ(bar_lengths(canvas, grey).size(), 3u);  // swatch + two bars
  EXPECT_TRUE(bar_lengths(canvas, tilelight::plot::series_colour(0)).empty());
}

TEST(BarChart, ZeroValuesDrawNoBar) {
  const Rgba8Canvas canvas = tilelight::plot::draw_bar_chart(two_bars(0.0, 3.0));
  EXPECT_EQ(bar_lengths(canvas, tilelight::plot::series_colour(0)).size(), 2u);  // swatch + one bar
}

TEST(BarChart, CanvasGrowsWithTheCategoriesAndTheLabels) {
  BarChart chart = two_bars(1.0, 2.0);
  const Rgba8Canvas small = tilelight::plot::draw_bar_chart(chart);
  chart.categories.push_back("a much longer category name than the others");
  chart.values.push_back({3.0});
  const Rgba8Canvas large = tilelight::plot::draw_bar_chart(chart);
  EXPECT_GT(large.height, small.height);
  EXPECT_GT(large.width, small.width);
}

TEST(BarChart, RejectsChartsItCannotDraw) {
  BarChart chart = two_bars(1.0, 2.0);
  chart.categories.clear();
  chart.values.clear();
  EXPECT_EQ(message_of(chart), "bar chart 't': no categories");

  chart = two_bars(1.0, 2.0);
  chart.series.clear();
  EXPECT_EQ(message_of(chart), "bar chart 't': no series");

  chart = two_bars(1.0, 2.0);
  chart.colours = {Rgba8{0, 0, 0, 255}, Rgba8{1, 1, 1, 255}};
  EXPECT_EQ(message_of(chart), "bar chart 't': 2 colours for 1 series");

  chart = two_bars(1.0, 2.0);
  chart.values.pop_back();
  EXPECT_EQ(message_of(chart), "bar chart 't': 1 rows of values for 2 categories");

  chart = two_bars(1.0, 2.0);
  chart.values[1].push_back(3.0);
  EXPECT_EQ(message_of(chart), "bar chart 't': category 1 has 2 values, expected 1");

  chart = two_bars(1.0, -2.0);
  EXPECT_EQ(message_of(chart), "bar chart 't': value -2 of category 'b', series 'light' is not finite and >= 0");
}

}  // namespace
