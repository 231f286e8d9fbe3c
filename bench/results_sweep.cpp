// tilelight_sweep: every design choice of the tile-classified light pass measured side by side
// in one process (issue 4, target 2). For each comparison it prints a markdown table on stdout
// and writes a bar chart; DIR/results.json holds every number. Progress goes to stderr.
//
//   tilelight_sweep [--frames N] [--out DIR] [--sizes 720p,1080p,1440p] [--device ...] [--quick]

#include "sweep/measurement.h"
#include "sweep/sweep_charts.h"
#include "sweep/sweep_json.h"
#include "sweep/sweep_options.h"
#include "sweep/sweep_plan.h"
#include "sweep/sweep_tables.h"

#include "plot/bar_chart.h"
#include "tilelight/context.h"
#include "tilelight/scene.h"
#include "tilelight_app/output_files.h"

#include <fmt/format.h>

#include <cstdlib>
#include <iostream>
#include <map>

namespace {

using namespace tilelight;
using namespace tilelight::sweep;

std::vector<const Measurement*> rows_of(const Comparison& c, const std::vector<Measurement>& measurements) {
  std::map<std::string, const Measurement*> by_key;
  for (const Measurement& m : measurements) by_key[m.key] = &m;
  std::vector<const Measurement*> rows;
  for (const std::string& key : c.keys) rows.push_back(by_key.at(key));
  return rows;
}

int run_sweep(const SweepOptions& options) {
  ContextOptions context_options;
  context_options.device = options.device;
  const Context context(context_options);
  app::OutputFiles files(options.out);  // proves --out writable before the long part
  const SweepPlan plan = make_sweep_plan(options);
  const std::vector<Measurement> measurements =
      measure_round_robin(context, make_demo_scene(), plan.configurations, options.frames, std::cerr);

  const char* threads = std::getenv("LP_NUM_THREADS");
  std::cout << fmt::format("Device: {}, {}x MSAA, median of {} frame(s) after 1 warm-up frame (configurations "
                           "measured round-robin), LP_NUM_THREADS={}\n",
                           context.device_name(), measurements.front().msaa_samples, options.frames,
                           threads != nullptr ? threads : "(default)");
  for (const Comparison& c : plan.comparisons) {
    const std::vector<const Measurement*> rows = rows_of(c, measurements);
    std::cout << "\n### " << c.title << "\n\n" << markdown_table(c, rows);
    files.stage(c.id + ".png", [&](const std::filesystem::path& p) {
      plot::write_bar_chart_png(p, comparison_chart(c, rows));
    });
  }
  const SweepRun run{context.device_name(), threads != nullptr ? threads : "", &options, &plan, &measurements};
  files.stage_text("results.json", results_json(run));
  files.commit();
  std::cerr << "wrote " << (files.folder() / "results.json").string() << " and one PNG per comparison\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  SweepOptions options;
  int exit_code = 0;
  try {
    if (!parse_sweep_options(argc, argv, options, exit_code, std::cout, std::cerr)) return exit_code;
    return run_sweep(options);
  } catch (const std::exception& e) {
    std::cerr << "tilelight_sweep: error: " << e.what() << '\n';
    return 1;
  }
}
