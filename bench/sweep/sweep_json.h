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
  std::vector<std::string> scene_warnings;  // the loader's lines, as printed on stderr
};

// {"device", "memory_bandwidth_bytes_per_s" (null: unknown, gbuffer_bound.h), "frames",
//  "warmup_frames", "schedule", "camera", "scene" (null: procedural), "scene_triangles",
//  "scene_warnings" [lines, as tilelight's report.json], "sizes", "lavapipe_threads",
//  "configurations": [{key, width, height, msaa_samples, tile_size, path, permutations,
//                      coalesce, pipelines, tiles, rectangles {uncoalesced, coalesced}, baselines,
//                      cull, culled {gbuffer_batches, shadow_batches},
//                      timings_ms {...medians}, frame_timings_ms [{...} per frame],
//                      classified_light_ms, speedup, speedup_over_dynamic,
//                      frame_ratios {light_vs_naive, light_vs_dynamic, whole_frame_vs_naive,
//                                    whole_frame_vs_dynamic: {median, min, max} or null},
//                      gbuffer_bytes, gbuffer_read_bound_ms (null: unknown), equivalence {...}}],
//  "comparisons": [{id, title, image, configurations: [key...]}]}; milliseconds to 3 decimals,
//  ratios to 2.
std::string results_json(const SweepRun& run);

}  // namespace tilelight::sweep
