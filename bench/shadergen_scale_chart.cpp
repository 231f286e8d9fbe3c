// shadergen_scale_chart: the chart of docs/results.md k5, drawn from the --json file of
// shadergen_scale_bench. Two grouped bar charts, one above the other, in one PNG: wall and CPU
// seconds per domain, then peak RSS per domain; each domain's category names its distinct
// sources, so both read as "against sources".
//
//   shadergen_scale_chart SCALE_JSON OUT_PNG
//
// Exit 0 on success; 1 when the JSON cannot be read or holds no successful one-machine build
// (the message names the file); 2 on a usage error.
#include "plot/bar_chart.h"

#include <atomic_file/atomic_file.h>
#include <tilelight/picture/png.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using tilelight::Rgba8Canvas;
namespace plot = tilelight::plot;

struct DomainFigures {
  int features = 0;
  long sources = 0;
  double wall_s = 0.0, cpu_s = 0.0, rss_mib = 0.0;
};

// "16 features, 49,152 sources": thousands separated, as the tables in results.md print them.
std::string category_of(const DomainFigures& d) {
  std::string digits = std::to_string(d.sources), grouped;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) grouped += ',';
    grouped += digits[i];
  }
  return std::to_string(d.features) + " features, " + grouped + " sources";
}

// The successful one-machine builds of the bench's "domains" array, in its order.
std::vector<DomainFigures> domains_of(const nlohmann::json& json) {
  std::vector<DomainFigures> domains;
  for (const nlohmann::json& row : json.at("domains")) {
    const nlohmann::json& build = row.at("build");
    if (!build.at("ok").get<bool>()) continue;
    domains.push_back({row.at("features").get<int>(), build.at("sources").get<long>(), build.at("wall_s").get<double>(),
                       build.at("cpu_s").get<double>(), build.at("peak_rss_mib").get<double>()});
  }
  return domains;
}

// One bar group per domain; `values` gives a domain's bar per series.
plot::BarChart domain_chart(std::string title, std::string value_axis, std::vector<std::string> series,
                            const std::vector<DomainFigures>& domains,
                            const std::function<std::vector<double>(const DomainFigures&)>& values) {
  plot::BarChart chart;
  chart.title = std::move(title);
  chart.category_axis = "domain";
  chart.value_axis = std::move(value_axis);
  chart.series = std::move(series);
  for (const DomainFigures& d : domains) {
    chart.categories.push_back(category_of(d));
    chart.values.push_back(values(d));
  }
  return chart;
}

plot::BarChart time_chart(const std::vector<DomainFigures>& domains) {
  plot::BarChart chart = domain_chart("shadergen cold build of generated domains, 2 compile jobs", "seconds",
                                      {"wall", "CPU (user + system)"}, domains, [](const DomainFigures& d) {
                                        return std::vector<double>{d.wall_s, d.cpu_s};
                                      });
  chart.decimals = 1;
  return chart;
}

plot::BarChart memory_chart(const std::vector<DomainFigures>& domains) {
  plot::BarChart chart = domain_chart("peak resident memory of the same builds", "peak RSS (MiB)", {"peak RSS"},
                                      domains, [](const DomainFigures& d) { return std::vector<double>{d.rss_mib}; });
  chart.colours = {plot::series_colour(2)};
  chart.decimals = 0;
  return chart;
}

// `top` above `bottom` on one white canvas as wide as the wider of the two.
Rgba8Canvas stacked(const Rgba8Canvas& top, const Rgba8Canvas& bottom) {
  Rgba8Canvas out = Rgba8Canvas::filled(std::max(top.width, bottom.width), top.height + bottom.height,
                                        tilelight::Rgba8{255, 255, 255, 255});
  auto copy = [&](const Rgba8Canvas& part, std::uint32_t y0) {
    for (std::uint32_t y = 0; y < part.height; ++y)
      std::memcpy(&out.pixels[(std::size_t{y0 + y} * out.width) * 4], &part.pixels[std::size_t{y} * part.width * 4],
                  std::size_t{part.width} * 4);
  };
  copy(top, 0);
  copy(bottom, top.height);
  return out;
}

int run(const fs::path& json_path, const fs::path& png_path) {
  std::ifstream in(json_path);
  nlohmann::json json = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (!in || json.is_discarded() || !json.is_object() || !json.contains("domains")) {
    std::cerr << json_path.string() << ": error: not the --json file of shadergen_scale_bench\n";
    return 1;
  }
  std::vector<DomainFigures> domains;
  try {
    domains = domains_of(json);
  } catch (const nlohmann::json::exception& e) {
    std::cerr << json_path.string() << ": error: " << e.what() << "\n";
    return 1;
  }
  if (domains.empty()) {
    std::cerr << json_path.string() << ": error: no successful one-machine build to draw\n";
    return 1;
  }
  const Rgba8Canvas canvas =
      stacked(plot::draw_bar_chart(time_chart(domains)), plot::draw_bar_chart(memory_chart(domains)));
  const std::vector<std::uint8_t> png = tilelight::encode_png(canvas.width, canvas.height, canvas.pixels);
  if (auto failure =
          atomic_file::write(png_path, std::string_view(reinterpret_cast<const char*>(png.data()), png.size()))) {
    std::cerr << png_path.string() << ": error: " << atomic_file::describe(*failure) << "\n";
    return 1;
  }
  std::cerr << "wrote " << png_path.string() << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3 || std::strcmp(argv[1], "--help") == 0) {
    std::cerr << "usage: shadergen_scale_chart SCALE_JSON OUT_PNG\n"
                 "  SCALE_JSON: the --json file of shadergen_scale_bench; OUT_PNG: the chart to write\n";
    return argc == 2 && std::strcmp(argv[1], "--help") == 0 ? 0 : 2;
  }
  try {
    return run(argv[1], argv[2]);
  } catch (const std::exception& e) {  // a chart the plot library refuses, or no memory
    std::cerr << "shadergen_scale_chart: error: " << e.what() << "\n";
    return 1;
  }
}
