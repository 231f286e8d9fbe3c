#pragma once
// results.json: every number the sweep measured, with the device and the settings.

#include "measurement.h"
#include "sweep_options.h"
#include "sweep_plan.h"

#include <string>
#include <vector>

namespace tilelight::sweep {

struct SweepRun {
  std::string device;
  std::string lavapipe_threads;  // LP_NUM_THREADS as set, or "" (driver default)
  const SweepOptions* options = nullptr;
  const SweepPlan* plan = nullptr;
  const std::vector<Measurement>* measurements = nullptr;  // in plan->configurations order
  std::string scene;                                       // the --scene file's name; "" = the procedural scene
  std::uint64_t scene_triangles = 0;
};

// {"device", "frames", "warmup_frames", "schedule", "camera", "scene" (null: procedural),
//  "scene_triangles", "sizes", "lavapipe_threads",
//  "configurations": [{key, width, height, msaa_samples, tile_size, path, permutations,
//                      coalesce, pipelines, tiles, rectangles {uncoalesced, coalesced},
//                      timings_ms {...}, classified_light_ms, speedup, equivalence {...}}],
//  "comparisons": [{id, title, image, configurations: [key...]}]}; milliseconds to 3 decimals.
std::string results_json(const SweepRun& run);

}  // namespace tilelight::sweep
