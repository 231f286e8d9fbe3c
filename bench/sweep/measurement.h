#pragma once
// One configuration of the renderer measured: medians of every stage over the timed frames,
// the primitive counts, and whether the classified frame still equals the naive one.

#include "spec_builds.h"

#include "tilelight/app/frame_ratios.h"
#include "tilelight/app/report.h"
#include "tilelight/render/tile_renderer.h"
#include "tilelight/scene/scene.h"
#include "tilelight/vulkan/context.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace tilelight::sweep {

struct Measurement {
  std::string key;  // configuration_key(options): unique per configuration
  RendererOptions options;
  std::uint32_t frames = 0;
  std::uint32_t msaa_samples = 0;
  std::uint32_t pipelines = 0;   // lighting pipelines the tile pass binds (32 or 96; 8 for --light-kinds branch)
  double tile_pipelines_ms = 0;  // host time their creation took (TileRenderer::tile_pipelines_ms())
  // The kinds comparison's rows: the light spec of the row's build compiled by shadergen (spec_builds.h).
  std::optional<SpecBuild> spec_build;
  std::uint32_t tiles = 0;
  TilePrimitive primitive = TilePrimitive::triangles;  // what the tile pass drew (auto resolved)
  std::uint32_t primitives_uncoalesced = 0, primitives_coalesced = 0, rectangles = 0;
  std::uint32_t sky_tiles = 0;              // tiles with the SKY property: cheap for every method
  CulledBatches culled;                     // mesh batches the scene passes skipped
  app::MedianTimings timings;               // per field, the median over frame_timings
  std::vector<FrameTimings> frame_timings;  // every timed frame, in order
  app::Equivalence equivalence;             // classified vs naive
  app::Equivalence dynamic_equivalence;     // dynamic vs naive

  // The index build of whichever path ran (the other one is 0).
  double index_build() const { return timings.index_build_cpu + timings.index_build_gpu; }
  // What the classified frame spends on lighting: classification + index build + tiled light.
  double classified_light() const { return timings.classification + index_build() + timings.tiled_light; }
  // naive light / classified_light(); 0 when nothing was timed.
  double speedup() const;
  // dynamic light / classified_light(): the speed-up over per-pixel branching.
  double speedup_over_dynamic() const;
  // The classified frame over the baselines, frame by frame (frame_ratios.h): what the
  // whole-frame table reports, robust to drift between frames.
  app::FrameRatios ratios() const { return app::frame_ratios(frame_timings); }
};

// Medians of every field of `frames` (precondition: not empty). app::median_timings() takes the
// stages; the whole frames, the plain G-buffer and the floor are taken here as well, so the sweep
// reports them whichever fields that function covers.
app::MedianTimings all_medians(const std::vector<FrameTimings>& frames);

// "1280x720 tile 4 cpu optimised coalesced auto camera default msaa auto raster": names a
// configuration in keys and progress lines; the word after "coalesced" is the primitive asked for
// (auto, points or triangles). Baselines other than the default `both` end it ("... baselines
// all"), so the keys of every existing configuration stay as they were.
std::string configuration_key(const RendererOptions& options);

// Makes one renderer per configuration and renders one untimed warm-up frame with each, then
// `frames` timed rounds (precondition: frames >= 1), each round one frame of every
// configuration in turn: on a shared machine, a change of load then hits every configuration
// alike instead of whichever happened to be measured at the time. Finally reads both images
// of each back and compares them. Progress lines go to `progress`. Results are in the order
// of `configurations`. `scene_for` gives the scene each configuration's renderer is made from,
// and may set its camera_pose (a fitted camera, tilelight/app/camera_choice.h): the renderer
// copies what it needs of both when it is made.
using SceneFor = std::function<const Scene&(RendererOptions&)>;
std::vector<Measurement> measure_round_robin(const Context& context, const SceneFor& scene_for,
                                             std::vector<RendererOptions> configurations, std::uint32_t frames,
                                             std::ostream& progress);

}  // namespace tilelight::sweep
