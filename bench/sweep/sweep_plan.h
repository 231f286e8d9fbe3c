#pragma once
// What the sweep measures: the six comparisons of issue 4, target 2, and the distinct renderer
// configurations they need (configurations shared between comparisons, like the default one,
// are measured once).

#include "measurement.h"
#include "sweep_options.h"

#include "tilelight/tile_renderer.h"

#include <string>
#include <vector>

namespace tilelight::sweep {

// What varies within one comparison; decides how its rows are named and charted.
enum class Facet { permutations, tile_size, index_path, coalescing, primitive, resolution, stages };

struct Comparison {
  Facet facet;
  std::string id;     // also the PNG's name: <id>.png
  std::string title;  // chart title and table heading
  std::vector<std::string> keys;  // configuration_key() of each row, in order
};

struct SweepPlan {
  std::vector<RendererOptions> configurations;  // distinct, in the order they are measured
  std::vector<Comparison> comparisons;          // results.md a) to g), in that order
};

// The defaults every comparison starts from: the first size, tile 4, CPU path, optimised
// permutations, coalesced, default camera, automatic MSAA.
SweepPlan make_sweep_plan(const SweepOptions& options);

// The row's name in tables and charts, e.g. "optimised (32)", "tile 8", "GPU-driven",
// "uncoalesced", "1920x1080".
std::string row_label(Facet facet, const Measurement& m);

}  // namespace tilelight::sweep
