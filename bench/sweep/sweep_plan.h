#pragma once
// What the sweep measures: the design-choice comparisons (permutations, tile size, index path,
// coalescing, primitive, resolution, stages) and the baselines (classified vs dynamic vs naive
// for every camera, size and MSAA mode), and the distinct renderer configurations they need
// (configurations shared between comparisons, like the default one, are measured once).

#include "measurement.h"
#include "sweep_options.h"

#include "tilelight/render/tile_renderer.h"

#include <string>
#include <vector>

namespace tilelight::sweep {

// What varies within one comparison; decides how its rows are named and charted.
enum class Facet { permutations, tile_size, index_path, coalescing, primitive, resolution, stages, baselines, kinds };

struct Comparison {
  Facet facet;
  std::string id;                 // also the PNG's name: <id>.png
  std::string title;              // chart title and table heading
  std::vector<std::string> keys;  // configuration_key() of each row, in order
};

struct SweepPlan {
  std::vector<RendererOptions> configurations;  // distinct, in the order they are measured
  std::vector<Comparison> comparisons;          // results.md a) to g), then the baselines
};

// The defaults every comparison starts from: the first size, tile 4, CPU path, optimised
// permutations, coalesced, default camera, automatic MSAA, both baselines. Only the comparisons
// named in options.only (all if it is empty).
SweepPlan make_sweep_plan(const SweepOptions& options);

// The row's name in tables and charts, e.g. "optimised (32)", "tile 8", "GPU-driven",
// "uncoalesced", "1920x1080", "4x 1280x720 street".
std::string row_label(Facet facet, const Measurement& m);

}  // namespace tilelight::sweep
